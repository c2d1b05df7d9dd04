// SHA-256 digests (OpenSSL's libcrypto), as lower-case hex: the content hashes that decide
// whether a cached result (a POV-Ray reference, an accelerator) still matches its inputs.
#pragma once

#include <string>
#include <string_view>

namespace rtlab {

std::string sha256Hex(std::string_view bytes);

// Digest of a file's bytes; throws rtlab::Error naming the file when it cannot be read.
std::string sha256OfFile(const std::string& path);

}  // namespace rtlab
