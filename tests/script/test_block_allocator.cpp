// BlockAllocator: reuse of freed small blocks, alignment, content kept across
// resizes between the small classes and the system's blocks. (The Vm's memory
// budget over it: test_vm.cpp.)
#include <doctest/doctest.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "script/block_allocator.h"

using squawk::script::BlockAllocator;

namespace {

bool aligned(const void* p) {
  return reinterpret_cast<uintptr_t>(p) % BlockAllocator::kAlign == 0;
}

}  // namespace

TEST_CASE("a freed small block is the next one of its class") {
  BlockAllocator a;
  void* p = a.resize(nullptr, 0, 40);
  void* q = a.resize(nullptr, 0, 40);
  REQUIRE(p);
  REQUIRE(q);
  CHECK(p != q);
  a.release(p, 40);
  CHECK(a.resize(nullptr, 0, 33) == p);  // 33 and 40 share the 48-byte class
  void* r = a.resize(nullptr, 0, 40);
  CHECK(r != p);
  a.release(q, 40);
  a.release(r, 40);
  a.release(p, 33);
  CHECK(a.chunk_bytes() == BlockAllocator::kChunkBytes);
}

TEST_CASE("many blocks fill chunks and reuse them after release") {
  BlockAllocator a;
  std::vector<void*> blocks;
  for (int i = 0; i < 10000; ++i) blocks.push_back(a.resize(nullptr, 0, 1 + i % 256));
  const size_t held = a.chunk_bytes();
  CHECK(held > BlockAllocator::kChunkBytes);
  for (int i = 0; i < 10000; ++i) a.release(blocks[i], 1 + i % 256);
  for (int i = 0; i < 10000; ++i) blocks[i] = a.resize(nullptr, 0, 1 + i % 256);
  CHECK(a.chunk_bytes() == held);  // the same sizes again: no new chunk
  for (int i = 0; i < 10000; ++i) a.release(blocks[i], 1 + i % 256);
}

TEST_CASE("every block is aligned, small or large") {
  BlockAllocator a;
  std::vector<std::pair<void*, size_t>> blocks;
  for (size_t n = 1; n <= 600; ++n) {
    void* p = a.resize(nullptr, 0, n);
    REQUIRE(p);
    CHECK(aligned(p));
    std::memset(p, 0xab, n);
    blocks.emplace_back(p, n);
  }
  for (auto& [p, n] : blocks) a.release(p, n);
}

TEST_CASE("resizing keeps the content across the small classes and the system's blocks") {
  BlockAllocator a;
  const size_t sizes[] = {5, 16, 17, 100, 256, 257, 4000, 300, 200, 12, 1};
  auto* p = static_cast<unsigned char*>(a.resize(nullptr, 0, sizes[0]));
  for (size_t k = 0; k < sizes[0]; ++k) p[k] = static_cast<unsigned char>(k * 7);
  for (size_t i = 1; i < std::size(sizes); ++i) {
    const size_t old = sizes[i - 1];
    const size_t now = sizes[i];
    p = static_cast<unsigned char*>(a.resize(p, old, now));
    REQUIRE(p);
    CHECK(aligned(p));
    for (size_t k = 0; k < std::min(old, now); ++k)
      REQUIRE(p[k] == static_cast<unsigned char>(k * 7));
    for (size_t k = old; k < now; ++k) p[k] = static_cast<unsigned char>(k * 7);
  }
  a.release(p, sizes[std::size(sizes) - 1]);
  a.release(nullptr, 10);  // nothing
}
