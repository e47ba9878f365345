// Fuzz target: `pak metrics`'s packing reader, the SVG reader followed by finding the
// container and the elements (by layer, else by the largest shape) and their regions.
#include "fuzz_input.hpp"
#include "pak/io/packing_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return pak::fuzz::readAcceptingInputErrors([&] {
    pak::packingFromDocument(pak::readSvgString(pak::fuzz::textOf(data, size), "fuzz.svg"));
  });
}
