// One member of a ZIP archive, streamed out (BlueSky ships its runway data as
// navdata/apt.zip holding apt.dat).
//
// Supported: stored (method 0) and deflate (method 8) members, found through
// the central directory. Refused with a Status naming the archive: ZIP64,
// encryption, other methods, truncated or inconsistent headers, a CRC-32 or
// size mismatch, a member that inflates past its declared size.
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include "core/status.h"

namespace squawk::zip {

// Receives the member's bytes in order, in chunks of at most 256 KiB; an error
// it returns stops the read and is returned as is.
using Sink = std::function<Status(std::string_view chunk)>;

// `archive`: the whole archive's bytes; `where` names it in errors. Any bytes
// give the member's contents or an error, never a crash (fuzz_navdb).
Status read_member(std::string_view archive, std::string_view member, const std::string& where, const Sink& sink);

}  // namespace squawk::zip
