#include "pak/io/message_text.hpp"

#include <cstdint>
#include <cstdio>

namespace pak {
namespace {

// Length of the valid UTF-8 sequence starting at `at`, or 0 if the byte there does not start one.
std::size_t utf8SequenceLength(std::string_view text, std::size_t at) {
  const auto byte = [&](std::size_t i) { return static_cast<std::uint8_t>(text[i]); };
  const std::uint8_t lead = byte(at);
  if (lead < 0x80) return 1;
  std::size_t length = 0;
  std::uint32_t min = 0, code = 0;
  if ((lead & 0xE0) == 0xC0) length = 2, min = 0x80, code = lead & 0x1F;
  else if ((lead & 0xF0) == 0xE0) length = 3, min = 0x800, code = lead & 0x0F;
  else if ((lead & 0xF8) == 0xF0) length = 4, min = 0x10000, code = lead & 0x07;
  else return 0;
  if (at + length > text.size()) return 0;
  for (std::size_t k = 1; k < length; ++k) {
    if ((byte(at + k) & 0xC0) != 0x80) return 0;
    code = (code << 6) | (byte(at + k) & 0x3F);
  }
  // Overlong forms, UTF-16 surrogates and code points past U+10FFFF are not UTF-8.
  if (code < min || (code >= 0xD800 && code <= 0xDFFF) || code > 0x10FFFF) return 0;
  return length;
}

std::string hexByte(std::uint8_t byte) {
  char text[8];
  std::snprintf(text, sizeof text, "\\x%02X", byte);
  return text;
}

}  // namespace

std::string oneLine(std::string_view text, std::size_t maxBytes) {
  std::string out;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t length = utf8SequenceLength(text, at);
    std::string piece;
    const char c = text[at];
    if (length == 0) piece = hexByte(static_cast<std::uint8_t>(c));
    else if (c == '\n') piece = "\\n";
    else if (c == '\r') piece = "\\r";
    else if (c == '\t') piece = "\\t";
    else if (length == 1 && (static_cast<std::uint8_t>(c) < 0x20 || c == 0x7F)) piece = hexByte(static_cast<std::uint8_t>(c));
    else piece = std::string(text.substr(at, length));
    if (out.size() + piece.size() > maxBytes) return out + "…";  // whole pieces: never half a character
    out += piece;
    at += length == 0 ? 1 : length;
  }
  return out;
}

bool isValidUtf8(std::string_view text) {
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t length = utf8SequenceLength(text, at);
    if (length == 0) return false;
    at += length;
  }
  return true;
}

std::string validUtf8(std::string_view text, std::size_t* replaced) {
  std::string out;
  out.reserve(text.size());
  std::size_t count = 0;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t length = utf8SequenceLength(text, at);
    if (length == 0) {
      out += "\xEF\xBF\xBD";  // U+FFFD REPLACEMENT CHARACTER
      ++count;
      ++at;
    } else {
      out.append(text.substr(at, length));
      at += length;
    }
  }
  if (replaced) *replaced = count;
  return out;
}

}  // namespace pak
