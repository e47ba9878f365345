#include "io/rgb_components.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

namespace pak {
namespace {

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

// A plain number with a fraction ("12.5", "1e2"): its rounded, clamped integer; else nullopt.
std::optional<int> roundedComponent(std::string_view text) {
  const std::string_view s = trimmed(text);
  if (s.empty() || s.back() == '%' || s.find_first_of(".eE") == std::string_view::npos) return std::nullopt;
  double v = 0.0;
  const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (error != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return static_cast<int>(std::lround(std::clamp(v, 0.0, 255.0)));
}

bool startsRgb(std::string_view s, std::size_t at) {
  if (at + 4 > s.size()) return false;
  for (std::size_t k = 0; k < 3; ++k)
    if (std::tolower(static_cast<unsigned char>(s[at + k])) != "rgb"[k]) return false;
  return s[at + 3] == '(' && (at == 0 || !std::isalnum(static_cast<unsigned char>(s[at - 1])));
}

}  // namespace

std::optional<std::string> roundedRgbComponents(std::string_view value) {
  std::string out;
  bool changed = false;
  std::size_t copied = 0;
  for (std::size_t at = 0; at < value.size(); ++at) {
    if (!startsRgb(value, at)) continue;
    const std::size_t open = at + 4, close = value.find(')', open);
    if (close == std::string_view::npos) break;
    std::string inside;
    bool roundedHere = false;
    for (std::size_t begin = open; begin <= close;) {
      std::size_t comma = value.find(',', begin);
      if (comma == std::string_view::npos || comma > close) comma = close;
      const std::string_view component = value.substr(begin, comma - begin);
      if (const std::optional<int> v = roundedComponent(component)) {
        inside += std::to_string(*v);
        roundedHere = true;
      } else {
        inside += component;
      }
      if (comma < close) inside += ',';
      begin = comma + 1;
    }
    if (roundedHere) {
      out.append(value.substr(copied, open - copied));
      out += inside;
      copied = close;
      changed = true;
    }
    at = close;
  }
  if (!changed) return std::nullopt;
  out.append(value.substr(copied));
  return out;
}

}  // namespace pak
