// Appending fixed-width little-endian-as-stored values to a byte string: the
// building blocks of Simulation::snapshot(). Doubles are written bit for bit,
// so two images are equal iff every value is bit-identical.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace squawk::sim::bytes {

template <class T>
inline void put(std::string& out, T v) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  out.append(b, sizeof(T));
}
inline void put_str(std::string& out, const std::string& s) {
  put<int64_t>(out, static_cast<int64_t>(s.size()));
  out.append(s);
}
template <class T>
inline void put_vec(std::string& out, const std::vector<T>& v) {
  put<int64_t>(out, static_cast<int64_t>(v.size()));
  for (const T& x : v) put<T>(out, x);
}

}  // namespace squawk::sim::bytes
