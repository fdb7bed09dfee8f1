#include "script/block_allocator.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>

#if defined(__SANITIZE_ADDRESS__)
#define SQUAWK_BLOCK_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SQUAWK_BLOCK_ASAN 1
#endif
#endif

#ifdef SQUAWK_BLOCK_ASAN
#include <sanitizer/asan_interface.h>
#define SQUAWK_POISON(p, n) ASAN_POISON_MEMORY_REGION((p), (n))
#define SQUAWK_UNPOISON(p, n) ASAN_UNPOISON_MEMORY_REGION((p), (n))
#else
#define SQUAWK_POISON(p, n) ((void)(p), (void)(n))
#define SQUAWK_UNPOISON(p, n) ((void)(p), (void)(n))
#endif

namespace squawk::script {

namespace {

constexpr size_t kChunkHeader = BlockAllocator::kAlign;  // [bytes] the link to the next chunk

}  // namespace

BlockAllocator::~BlockAllocator() {
  while (chunk_list_) {
    void* next = nullptr;
    SQUAWK_UNPOISON(chunk_list_, kChunkBytes);
    std::memcpy(&next, chunk_list_, sizeof next);
    std::free(chunk_list_);
    chunk_list_ = next;
  }
}

bool BlockAllocator::refill() {
  // The rest of the newest chunk (a multiple of kAlign, under kMaxSmall) joins its class.
  if (bump_ < end_) give(bump_, class_of(static_cast<size_t>(end_ - bump_)));
  char* chunk = static_cast<char*>(std::malloc(kChunkBytes));
  if (!chunk) {
    bump_ = end_ = nullptr;
    return false;
  }
  std::memcpy(chunk, &chunk_list_, sizeof chunk_list_);
  chunk_list_ = chunk;
  ++chunks_;
  bump_ = chunk + kChunkHeader;
  end_ = chunk + kChunkBytes;
  SQUAWK_POISON(bump_, static_cast<size_t>(end_ - bump_));
  return true;
}

void* BlockAllocator::take(size_t cls) {
  const size_t bytes = (cls + 1) * kAlign;
  if (Free* f = free_[cls]) {
    SQUAWK_UNPOISON(f, bytes);
    free_[cls] = f->next;
    return f;
  }
  if (static_cast<size_t>(end_ - bump_) < bytes && !refill()) return nullptr;
  void* p = bump_;
  bump_ += bytes;
  SQUAWK_UNPOISON(p, bytes);
  return p;
}

void BlockAllocator::give(void* block, size_t cls) {
  SQUAWK_UNPOISON(block, (cls + 1) * kAlign);  // (chunk space left over by refill is poisoned)
  Free* f = static_cast<Free*>(block);
  f->next = free_[cls];
  free_[cls] = f;
  SQUAWK_POISON(block, (cls + 1) * kAlign);
}

void BlockAllocator::release(void* block, size_t size) {
  if (!block) return;
  if (size <= kMaxSmall) {
    give(block, class_of(size));
  } else {
    std::free(block);
  }
}

void* BlockAllocator::resize(void* block, size_t old_size, size_t new_size) {
  const bool new_small = new_size <= kMaxSmall;
  if (!block) return new_small ? take(class_of(new_size)) : std::malloc(new_size);
  if (old_size > kMaxSmall && !new_small) return std::realloc(block, new_size);
  if (old_size <= kMaxSmall && new_small && class_of(old_size) == class_of(new_size)) return block;
  void* p = new_small ? take(class_of(new_size)) : std::malloc(new_size);
  if (!p) return nullptr;
  std::memcpy(p, block, std::min(old_size, new_size));
  release(block, old_size);
  return p;
}

}  // namespace squawk::script
