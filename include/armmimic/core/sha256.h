// SHA-256 (FIPS 180-4) of a file or a byte buffer, as lowercase hex: pinned downloads (the pose
// model) are checked against it before use.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "armmimic/core/status.h"

namespace armmimic {

std::string Sha256Hex(const std::uint8_t* data, std::size_t size);
// The file's digest in *hex; an unreadable file is an error naming it.
Status Sha256File(const std::string& path, std::string* hex);

}  // namespace armmimic
