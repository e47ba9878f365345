#pragma once
// Text from the input (attribute values, ids, file names, JSON keys) made fit for a one-line
// message: control characters and newlines escaped, bytes that are not UTF-8 shown as \xHH,
// and long text cut with "…". The CLI passes every message through oneLine, so that
// `pak: error: <where>: <what>` stays one line whatever a file holds.
#include <cstddef>
#include <string>
#include <string_view>

namespace pak {

// How much of a value a message quotes, and how long a whole message may be (bytes).
constexpr std::size_t kQuotedValueLength = 80;
constexpr std::size_t kMessageLength = 400;

// `text` escaped as above and cut to at most `maxBytes` bytes plus "…".
std::string oneLine(std::string_view text, std::size_t maxBytes = kMessageLength);

// A value to quote in a message: oneLine, cut at kQuotedValueLength.
inline std::string quotedValue(std::string_view text) { return oneLine(text, kQuotedValueLength); }

// Whether `text` starts with `prefix`; if so, drops it. For reading a library's message
// (nlohmann's, CLI11's) into ours without std::regex, whose libstdc++ matcher recurses once
// per character and overflows the stack on a long value.
inline bool consumePrefix(std::string_view& text, std::string_view prefix) {
  if (!text.starts_with(prefix)) return false;
  text.remove_prefix(prefix.size());
  return true;
}

// Whether `text` is valid UTF-8 (no overlong forms, no surrogates, nothing above U+10FFFF).
bool isValidUtf8(std::string_view text);

// `text` with each byte that does not start or continue a valid UTF-8 sequence replaced by
// U+FFFD; `replaced` counts them.
std::string validUtf8(std::string_view text, std::size_t* replaced = nullptr);

}  // namespace pak
