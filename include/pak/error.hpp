#pragma once
// Invalid input (a file, an SVG, a parameter) throws InputError: *where* (a file, "file:line",
// an element id or an --option) and *what* is wrong, apart; what() is "<where>: <what>". The
// CLI prints "pak: error: <where>: <what>" and exits with code 2. Programmer mistakes are
// assertions instead.
#include <cstdio>
#include <stdexcept>
#include <string>

namespace pak {

class InputError : public std::runtime_error {
 public:
  InputError(const std::string& where, const std::string& problem)
      : std::runtime_error(where.empty() ? problem : where + ": " + problem), where_(where), problem_(problem) {}

  const std::string& where() const { return where_; }      // empty: the message says where itself
  const std::string& problem() const { return problem_; }  // what is wrong, without `where`

 private:
  std::string where_, problem_;
};

// `error`, said to be at `where` when it says nowhere itself: a geometry routine deep inside a
// packer knows no file, the packer knows its scene's.
inline InputError attributed(const InputError& error, const std::string& where) {
  return error.where().empty() && !where.empty() ? InputError(where, error.problem()) : error;
}

// A number for a message, as a person would write it: 250, not 250.000000; 6 significant digits.
inline std::string messageNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

}  // namespace pak
