#pragma once
// What every fuzz target shares: the input as text, and which outcomes are normal. A reader
// either returns or rejects its input with InputError, which the CLI turns into one line and
// exit 2. Any other exception would reach the user as "internal error" (exit 1): it is
// reported and aborts, so that libFuzzer (and the replay) count it as a finding.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <typeinfo>

#include "pak/error.hpp"

namespace pak::fuzz {

inline std::string textOf(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

template <class Read>
int readAcceptingInputErrors(const Read& read) {
  try {
    read();
  } catch (const InputError&) {
    // Bad input, reported as such: the outcome we want.
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz: finding: %s escaped the reader: %s\n", typeid(e).name(), e.what());
    std::abort();
  }
  return 0;
}

}  // namespace pak::fuzz
