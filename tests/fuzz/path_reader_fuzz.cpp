// Fuzz target: the reader of the original RepulsionPak `.path` text format.
#include "fuzz_input.hpp"
#include "pak/io/path_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return pak::fuzz::readAcceptingInputErrors([&] { pak::readPathString(pak::fuzz::textOf(data, size), "fuzz.path"); });
}
