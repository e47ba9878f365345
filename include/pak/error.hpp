#pragma once
// Invalid input (a file, an SVG, a parameter) throws InputError, whose message says what is
// wrong and where: "<file>: <what and where>". The CLI prints "pak: error: <message>" and
// exits with code 2. Programmer mistakes are assertions instead.
#include <stdexcept>
#include <string>

namespace pak {

class InputError : public std::runtime_error {
 public:
  InputError(const std::string& where, const std::string& what)
      : std::runtime_error(where.empty() ? what : where + ": " + what) {}
};

}  // namespace pak
