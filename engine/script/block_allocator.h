// BlockAllocator: the allocator behind one Lua state's heap (lua_Alloc's
// reallocation, without the byte budget, which Vm keeps).
//
// Blocks of at most kMaxSmall bytes come from size classes kAlign bytes
// apart: each class has a free list (last freed, first reused), refilled
// from chunks of kChunkBytes taken from std::malloc. Chunks are owned by the
// allocator and freed only with it, and a freed block stays in its class, so
// the small-block memory it holds is at most the sum over the classes of
// each class's peak of live blocks, rounded up to a chunk. The Vm's byte
// budget counts the bytes Lua asks for, not this. Larger blocks go to
// std::malloc / std::realloc / std::free as they are.
// Every block is aligned to kAlign (as std::malloc's are).
//
// Contract (Lua's, lua_Alloc): a block is always resized and freed with the
// size it was last asked for (old_size below); sizes are in bytes. A failed
// request (the system refusing a chunk or a large block) returns nullptr and
// leaves the block as it was. Not thread-safe: one allocator per lua_State.
// Under AddressSanitizer free blocks and unused chunk space are poisoned, so
// a use after free of a small block is still reported.
#pragma once

#include <cstddef>

namespace squawk::script {

class BlockAllocator {
 public:
  static constexpr size_t kAlign = 16;              // [bytes] class step and alignment
  static constexpr size_t kMaxSmall = 256;          // [bytes] largest pooled block
  static constexpr size_t kChunkBytes = 64 * 1024;  // [bytes] one refill from the system

  BlockAllocator() = default;
  ~BlockAllocator();
  BlockAllocator(const BlockAllocator&) = delete;
  BlockAllocator& operator=(const BlockAllocator&) = delete;

  // A block of new_size bytes holding the first min(old_size, new_size)
  // bytes of `block` (nullptr: a fresh block, old_size ignored); nullptr
  // when the memory cannot be had (then `block` is unchanged). new_size > 0.
  void* resize(void* block, size_t old_size, size_t new_size);
  // Frees `block` (nullptr: nothing), last asked for with `size` bytes.
  void release(void* block, size_t size);

  // [bytes] taken from the system for small blocks (whole chunks).
  size_t chunk_bytes() const { return chunks_ * kChunkBytes; }

 private:
  static constexpr size_t kClasses = kMaxSmall / kAlign;
  static size_t class_of(size_t size) { return (size - 1) / kAlign; }  // size in [1, kMaxSmall]

  void* take(size_t cls);
  void give(void* block, size_t cls);
  bool refill();

  struct Free {
    Free* next;
  };
  Free* free_[kClasses] = {};
  char* bump_ = nullptr;  // unused space of the newest chunk: [bump_, end_)
  char* end_ = nullptr;
  void* chunk_list_ = nullptr;  // newest chunk; each chunk's first word links the next
  size_t chunks_ = 0;
};

}  // namespace squawk::script
