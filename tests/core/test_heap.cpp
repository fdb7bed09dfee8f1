#include <doctest/doctest.h>

#include <cstdlib>
#include <vector>

#include "core/heap.h"

// glibc's own allocator only: ASan replaces it, other C libraries lack mallinfo2.
#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__)
#include <malloc.h>

TEST_CASE("keep_freed_memory serves a 30 MiB block from the heap and keeps it after free") {
  // glibc's defaults would mmap this block and unmap it on free (its mmap
  // threshold starts at 128 KiB and rises only to the size of freed mmapped blocks).
  squawk::heap::keep_freed_memory();
  const size_t n = size_t{30} << 20;
  const struct mallinfo2 before = mallinfo2();
  size_t arena_with_block = 0;
  {
    std::vector<char> block(n, 1);
    const struct mallinfo2 during = mallinfo2();
    CHECK(during.hblkhd == before.hblkhd);  // not mmapped
    arena_with_block = during.arena;
    CHECK(arena_with_block >= before.arena + n);
  }
  const struct mallinfo2 after = mallinfo2();
  CHECK(after.arena == arena_with_block);  // not trimmed
  CHECK(after.fordblks >= n);              // free for the next block
  std::vector<char> again(n, 2);
  CHECK(mallinfo2().arena == arena_with_block);  // reused, the heap did not grow
}
#endif
