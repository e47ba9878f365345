// Fuzz target: the SVG reader (every .svg Pak opens: containers, elements, packings).
#include "fuzz_input.hpp"
#include "pak/io/svg_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return pak::fuzz::readAcceptingInputErrors([&] { pak::readSvgString(pak::fuzz::textOf(data, size), "fuzz.svg"); });
}
