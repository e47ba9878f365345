// Fuzz target: the animation-file (JSON script) reader of `pak animate`, and the keyframe
// tracks it yields sampled as the animation will sample them, looping and not.
#include "fuzz_input.hpp"
#include "pak/animation/keyframes.hpp"
#include "pak/io/animation_script_reader.hpp"

namespace {

template <class Keys, class Value>
void sampleAcrossTheLoop(const Keys& keys, Value fallback) {
  for (double t : {0.0, 0.25, 0.5, 0.999, 1.0})
    for (bool periodic : {false, true}) pak::sampleTrack(keys, t, fallback, periodic);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return pak::fuzz::readAcceptingInputErrors([&] {
    const pak::AnimationScript script = pak::parseAnimationScript(pak::fuzz::textOf(data, size), "fuzz.json", "anim");
    for (const pak::AnimatedElementSpec& element : script.elements) {
      sampleAcrossTheLoop(element.animation.rotation, 0.0);
      sampleAcrossTheLoop(element.animation.scale, 1.0);
      sampleAcrossTheLoop(element.animation.translation, pak::Vec2{});
      for (const auto& handle : element.animation.handles) sampleAcrossTheLoop(handle.offset, pak::Vec2{});
    }
  });
}
