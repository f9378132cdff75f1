#pragma once
// Base64 (RFC 4648, the standard alphabet with '=' padding): how a file travels inside a JSON
// document (an exercise bundle holds its mesh and preset this way).

#include <optional>
#include <string>

namespace palpate {

std::string encodeBase64(const std::string& bytes);

/// The bytes, or nullopt for text that is not canonical base64 (a character outside the
/// alphabet, a length not a multiple of four, padding anywhere but the end, or pad bits set);
/// whitespace is not allowed either.
std::optional<std::string> decodeBase64(const std::string& text);

}  // namespace palpate
