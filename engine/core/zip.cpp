#include "core/zip.h"

#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace squawk::zip {

namespace {

constexpr uint32_t kEndSig = 0x06054b50;      // end of central directory
constexpr uint32_t kCentralSig = 0x02014b50;  // central directory file header
constexpr uint32_t kLocalSig = 0x04034b50;    // local file header
constexpr size_t kEndSize = 22, kCentralSize = 46, kLocalSize = 30;
constexpr size_t kChunk = 256 * 1024;

uint16_t u16(std::string_view b, size_t at) {
  return static_cast<uint16_t>(static_cast<uint8_t>(b[at]) | static_cast<uint8_t>(b[at + 1]) << 8);
}
uint32_t u32(std::string_view b, size_t at) { return u16(b, at) | static_cast<uint32_t>(u16(b, at + 2)) << 16; }

struct Entry {
  uint16_t flags = 0, method = 0;
  uint32_t crc = 0, csize = 0, usize = 0, local = 0;
};

Result<Entry> find_entry(std::string_view a, std::string_view member, const std::string& where) {
  if (a.size() < kEndSize) return Status::corruption(where + ": not a ZIP archive (" + std::to_string(a.size()) + " bytes)");
  // The end record sits in the last 22 + 65535 (comment) bytes.
  size_t end = std::string_view::npos;
  const size_t lowest = a.size() > kEndSize + 65535 ? a.size() - kEndSize - 65535 : 0;
  for (size_t at = a.size() - kEndSize + 1; at-- > lowest;)
    if (u32(a, at) == kEndSig) {
      end = at;
      break;
    }
  if (end == std::string_view::npos) return Status::corruption(where + ": not a ZIP archive (no end of central directory)");
  const uint16_t count = u16(a, end + 10);
  const uint32_t cd_size = u32(a, end + 12), cd_at = u32(a, end + 16);
  if (cd_at == 0xffffffffu || count == 0xffff) return Status::unsupported(where + ": ZIP64 archives are not supported");
  if (uint64_t{cd_at} + cd_size > end) return Status::corruption(where + ": central directory lies outside the archive");
  size_t at = cd_at;
  for (uint16_t i = 0; i < count; ++i) {
    if (at + kCentralSize > end || u32(a, at) != kCentralSig)
      return Status::corruption(where + ": central directory entry " + std::to_string(i + 1) + " is damaged");
    Entry e;
    e.flags = u16(a, at + 8);
    e.method = u16(a, at + 10);
    e.crc = u32(a, at + 16);
    e.csize = u32(a, at + 20);
    e.usize = u32(a, at + 24);
    const size_t name_len = u16(a, at + 28), extra_len = u16(a, at + 30), comment_len = u16(a, at + 32);
    e.local = u32(a, at + 42);
    if (at + kCentralSize + name_len > end)
      return Status::corruption(where + ": central directory entry " + std::to_string(i + 1) + " is damaged");
    if (a.substr(at + kCentralSize, name_len) == member) return e;
    at += kCentralSize + name_len + extra_len + comment_len;
  }
  return Status::not_found(where + ": no member named '" + std::string(member) + "'");
}

Status inflate_to(std::string_view data, const Entry& e, const std::string& where, const Sink& sink, uint32_t& crc,
                  uint64_t& produced) {
  z_stream zs{};
  if (inflateInit2(&zs, -MAX_WBITS) != Z_OK) return Status::internal("zlib: inflateInit2 failed");
  std::vector<unsigned char> out(kChunk);
  zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
  zs.avail_in = static_cast<uInt>(data.size());
  Status st;
  int rc = Z_OK;
  while (rc != Z_STREAM_END) {
    zs.next_out = out.data();
    zs.avail_out = static_cast<uInt>(out.size());
    rc = inflate(&zs, Z_NO_FLUSH);
    if (rc == Z_BUF_ERROR || (rc == Z_OK && zs.avail_out == out.size())) {
      st = Status::corruption(where + ": deflate data ends early");
      break;
    }
    if (rc != Z_OK && rc != Z_STREAM_END) {
      st = Status::corruption(where + ": deflate data is damaged (" + (zs.msg ? zs.msg : "zlib error " + std::to_string(rc)) + ")");
      break;
    }
    const size_t n = out.size() - zs.avail_out;
    produced += n;
    if (produced > e.usize) {
      st = Status::corruption(where + ": member inflates past its declared " + std::to_string(e.usize) + " bytes");
      break;
    }
    crc = static_cast<uint32_t>(crc32(crc, out.data(), static_cast<uInt>(n)));
    st = sink(std::string_view(reinterpret_cast<const char*>(out.data()), n));
    if (!st.is_ok()) break;
  }
  inflateEnd(&zs);
  return st;
}

}  // namespace

Status read_member(std::string_view a, std::string_view member, const std::string& where, const Sink& sink) {
  SQUAWK_ASSIGN_OR_RETURN(const Entry e, find_entry(a, member, where));
  const std::string what = where + " member '" + std::string(member) + "'";
  if (e.flags & 1u) return Status::unsupported(what + " is encrypted");
  if (e.csize == 0xffffffffu || e.usize == 0xffffffffu) return Status::unsupported(what + ": ZIP64 is not supported");
  if (e.method != 0 && e.method != 8)
    return Status::unsupported(what + ": compression method " + std::to_string(e.method) + " (only stored and deflate)");
  if (uint64_t{e.local} + kLocalSize > a.size() || u32(a, e.local) != kLocalSig)
    return Status::corruption(what + ": local header is damaged");
  const uint64_t data_at = uint64_t{e.local} + kLocalSize + u16(a, e.local + 26) + u16(a, e.local + 28);
  if (data_at + e.csize > a.size()) return Status::corruption(what + ": data runs past the end of the archive");
  const std::string_view data = a.substr(data_at, e.csize);
  uint32_t crc = static_cast<uint32_t>(crc32(0, nullptr, 0));
  uint64_t produced = 0;
  if (e.method == 0) {
    if (e.csize != e.usize) return Status::corruption(what + ": stored member with two different sizes");
    for (size_t at = 0; at < data.size(); at += kChunk) {
      const std::string_view piece = data.substr(at, kChunk);
      crc = static_cast<uint32_t>(crc32(crc, reinterpret_cast<const Bytef*>(piece.data()), static_cast<uInt>(piece.size())));
      produced += piece.size();
      SQUAWK_RETURN_IF_ERROR(sink(piece));
    }
  } else {
    SQUAWK_RETURN_IF_ERROR(inflate_to(data, e, what, sink, crc, produced));
  }
  if (produced != e.usize)
    return Status::corruption(what + ": " + std::to_string(produced) + " bytes, the directory says " + std::to_string(e.usize));
  if (crc != e.crc) return Status::corruption(what + ": CRC-32 mismatch");
  return Status::ok();
}

}  // namespace squawk::zip
