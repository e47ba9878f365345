// The AnimationPak animation file (docs/animation-format.md): values and every error class.
#include "pak/io/animation_script_reader.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "pak/error.hpp"

namespace pak {
namespace {

namespace fs = std::filesystem;

const char* kExample = R"~({
  "slices": 100, "frames": 500, "loop": true, "duration": 10,
  "elements": [
    {"id": "star", "svg": "elements/star.svg", "count": 12,
     "rotation":    [{"t": 0, "value": 0}, {"t": 1, "value": 72}],
     "scale":       [{"t": 0, "value": 1}, {"t": 0.5, "value": 1.25}, {"t": 1, "value": 1}],
     "translation": [{"t": 0, "x": 0, "y": 0}, {"t": 0.5, "x": 10, "y": 0}, {"t": 1, "x": 0, "y": 0}],
     "handles": {"tail": [{"t": 0, "dx": 0, "dy": 0}, {"t": 0.5, "dx": 0, "dy": 12}, {"t": 1, "dx": 0, "dy": 0}]},
     "orientation": 90},
    {"id": "snake", "svg": "elements/snake.svg",
     "targets": [{"t": 0, "x": 100, "y": 50}, {"t": 0.5, "x": 100, "y": 150, "scale": 1.0, "rotation": 180}, {"t": 1, "x": 100, "y": 50}],
     "loop_to": "snake"},
    {"svg": "/abs/leaf.svg", "orientation": "random"}
  ]
})~";

AnimationScript parse(const std::string& json) { return parseAnimationScript(json, "anim.json", "/data/run"); }

std::string errorOf(const std::string& json) {
  try {
    parse(json);
  } catch (const InputError& error) {
    return error.what();
  }
  return "(no error)";
}

// One element around `element`'s members (a valid svg unless overridden).
std::string withElement(const std::string& members) {
  return R"({"elements": [{"svg": "a.svg")" + (members.empty() ? "" : ", " + members) + "}]}";
}

#define EXPECT_ERROR(json, text)                                              \
  do {                                                                        \
    const std::string message = errorOf(json);                                \
    EXPECT_NE(message.find("anim.json: "), std::string::npos) << message;     \
    EXPECT_NE(message.find(text), std::string::npos) << message;              \
  } while (false)

TEST(AnimationScriptReader, FullExample) {
  const AnimationScript script = parse(kExample);
  EXPECT_EQ(script.slices, 100);
  EXPECT_EQ(script.frames, 500);
  EXPECT_TRUE(script.loop);
  EXPECT_EQ(script.duration, 10.0);
  ASSERT_EQ(script.elements.size(), 3u);

  const AnimatedElementSpec& star = script.elements[0];
  EXPECT_EQ(star.id, "star");
  EXPECT_EQ(star.svg, "/data/run/elements/star.svg");
  EXPECT_EQ(star.count, 12);
  ASSERT_EQ(star.animation.rotation.size(), 2u);
  EXPECT_EQ(star.animation.rotation[1].t, 1.0);
  EXPECT_EQ(star.animation.rotation[1].value, 72.0);
  ASSERT_EQ(star.animation.scale.size(), 3u);
  EXPECT_EQ(star.animation.scale[1].t, 0.5);
  EXPECT_EQ(star.animation.scale[1].value, 1.25);
  ASSERT_EQ(star.animation.translation.size(), 3u);
  EXPECT_EQ(star.animation.translation[1].value, (Vec2{10, 0}));
  ASSERT_EQ(star.animation.handles.size(), 1u);
  EXPECT_EQ(star.animation.handles[0].name, "tail");
  ASSERT_EQ(star.animation.handles[0].offset.size(), 3u);
  EXPECT_EQ(star.animation.handles[0].offset[1].value, (Vec2{0, 12}));
  ASSERT_TRUE(star.orientation);
  EXPECT_EQ(*star.orientation, 90.0);
  EXPECT_TRUE(star.targets.empty());
  EXPECT_TRUE(star.loopTo.empty());

  const AnimatedElementSpec& snake = script.elements[1];
  EXPECT_EQ(snake.id, "snake");
  EXPECT_EQ(snake.count, 1);
  ASSERT_EQ(snake.targets.size(), 3u);
  EXPECT_EQ(snake.targets[1].t, 0.5);
  EXPECT_EQ(snake.targets[1].position, (Vec2{100, 150}));
  ASSERT_TRUE(snake.targets[1].scale);
  EXPECT_EQ(*snake.targets[1].scale, 1.0);
  ASSERT_TRUE(snake.targets[1].rotation);
  EXPECT_EQ(*snake.targets[1].rotation, 180.0);
  EXPECT_FALSE(snake.targets[0].scale);
  EXPECT_FALSE(snake.targets[0].rotation);
  EXPECT_EQ(snake.loopTo, "snake");
  EXPECT_FALSE(snake.orientation);  // none given: random

  const AnimatedElementSpec& leaf = script.elements[2];
  EXPECT_EQ(leaf.id, "element-2");
  EXPECT_EQ(leaf.svg, "/abs/leaf.svg");  // absolute: kept
  EXPECT_FALSE(leaf.orientation);
  EXPECT_EQ(leaf.count, 1);
}

TEST(AnimationScriptReader, Defaults) {
  const AnimationScript script = parse(withElement(""));
  const AnimationScript defaults;
  EXPECT_EQ(script.slices, defaults.slices);
  EXPECT_EQ(script.frames, defaults.frames);
  EXPECT_EQ(script.loop, defaults.loop);
  EXPECT_EQ(script.duration, defaults.duration);
  ASSERT_EQ(script.elements.size(), 1u);
  EXPECT_EQ(script.elements[0].id, "element-0");
  EXPECT_EQ(script.elements[0].svg, "/data/run/a.svg");
  EXPECT_TRUE(script.elements[0].animation.rotation.empty());
}

TEST(AnimationScriptReader, ReadsAFileRelativeToItsFolder) {
  const fs::path folder = fs::temp_directory_path() / ("pak-anim-test-" + std::to_string(::getpid()));
  fs::create_directories(folder);
  const fs::path file = folder / "anim.json";
  std::ofstream(file) << withElement(R"("id": "x")");
  const AnimationScript script = readAnimationScript(file.string());
  fs::remove_all(folder);
  ASSERT_EQ(script.elements.size(), 1u);
  EXPECT_EQ(script.elements[0].svg, (folder / "a.svg").string());
  EXPECT_NE(std::string(errorOf("")).find("not valid JSON"), std::string::npos);
  try {
    readAnimationScript((folder / "missing.json").string());
    FAIL() << "no error for a missing file";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("missing.json"), std::string::npos);
  }
}

TEST(AnimationScriptReader, NotJsonOrNotAnObject) {
  EXPECT_ERROR("{\"slices\": ", "not valid JSON");
  EXPECT_ERROR("[1, 2]", "must be a JSON object");
  EXPECT_ERROR(R"({"slices": 10})", "missing \"elements\"");
  EXPECT_ERROR(R"({"elements": []})", "elements: at least one element");
  EXPECT_ERROR(R"({"elements": {}})", "elements: must be an array");
  EXPECT_ERROR(R"({"elements": [3]})", "elements[0]: must be an object");
}

TEST(AnimationScriptReader, UnknownKeys) {
  EXPECT_ERROR(R"({"slice": 10, "elements": []})", "unknown key \"slice\"");
  EXPECT_ERROR(withElement(R"("rotaton": [])"), "elements[0]: unknown key \"rotaton\"");
  EXPECT_ERROR(withElement(R"("scale": [{"t": 0, "valeu": 1}])"), "elements[0].scale[0]: unknown key \"valeu\"");
  EXPECT_ERROR(withElement(R"("targets": [{"t": 0, "x": 0, "y": 0, "z": 1}])"), "elements[0].targets[0]: unknown key \"z\"");
}

TEST(AnimationScriptReader, Globals) {
  EXPECT_ERROR(R"({"slices": 1, "elements": []})", "slices: must be within [2, 1000]");
  EXPECT_ERROR(R"({"slices": 1001, "elements": []})", "slices: must be within [2, 1000]");
  EXPECT_ERROR(R"({"slices": 10.5, "elements": []})", "slices: must be a whole number");
  EXPECT_ERROR(R"({"slices": "10", "elements": []})", "slices: must be a number");
  EXPECT_ERROR(R"({"frames": 0, "elements": []})", "frames: must be within [1, 10000]");
  EXPECT_ERROR(R"({"frames": 10001, "elements": []})", "frames: must be within [1, 10000]");
  EXPECT_ERROR(R"({"duration": 0, "elements": []})", "duration: must be positive");
  EXPECT_ERROR(R"({"duration": -2, "elements": []})", "duration: must be positive");
  EXPECT_ERROR(R"({"loop": 1, "elements": []})", "loop: must be true or false");
}

TEST(AnimationScriptReader, Svg) {
  EXPECT_ERROR(R"({"elements": [{"id": "a"}]})", "elements[0]: missing \"svg\"");
  EXPECT_ERROR(R"({"elements": [{"svg": 3}]})", "elements[0].svg: must be a string");
  EXPECT_ERROR(R"({"elements": [{"svg": ""}]})", "elements[0].svg: must name an element file");
}

TEST(AnimationScriptReader, Count) {
  EXPECT_ERROR(withElement(R"("count": 0)"), "elements[0].count: must be within [1, 10000]");
  EXPECT_ERROR(withElement(R"("count": 10001)"), "elements[0].count: must be within [1, 10000]");
}

TEST(AnimationScriptReader, KeysSortedInRangeFinite) {
  EXPECT_ERROR(withElement(R"("rotation": [{"t": 0.5, "value": 0}, {"t": 0.2, "value": 1}])"),
               "elements[0].rotation[1].t: keys must be sorted by t");
  EXPECT_ERROR(withElement(R"("rotation": [{"t": 0.5, "value": 0}, {"t": 0.5, "value": 1}])"),
               "elements[0].rotation[1].t: keys must be sorted by t");
  EXPECT_ERROR(withElement(R"("rotation": [{"t": 1.5, "value": 0}])"), "elements[0].rotation[0].t: t must be within [0, 1]");
  EXPECT_ERROR(withElement(R"("rotation": [{"t": -0.1, "value": 0}])"), "elements[0].rotation[0].t: t must be within [0, 1]");
  // JSON has no NaN or infinity; a number beyond a double's range is refused while parsing.
  EXPECT_ERROR(withElement(R"("translation": [{"t": 0, "x": 1e999, "y": 0}])"), "not valid JSON");
  EXPECT_ERROR(withElement(R"("translation": [{"t": 0, "x": NaN, "y": 0}])"), "not valid JSON");
  EXPECT_ERROR(withElement(R"("translation": [{"t": 0, "x": 1}])"), "elements[0].translation[0]: missing \"y\"");
  EXPECT_ERROR(withElement(R"("rotation": [{"value": 0}])"), "elements[0].rotation[0]: missing \"t\"");
  EXPECT_ERROR(withElement(R"("rotation": {"t": 0})"), "elements[0].rotation: must be an array");
  EXPECT_ERROR(withElement(R"("handles": {"tail": [{"t": 0, "dx": 0, "dy": null}]})"),
               "elements[0].handles.tail[0].dy: must be a number");
  EXPECT_ERROR(withElement(R"("handles": [])"), "elements[0].handles: must be an object");
}

TEST(AnimationScriptReader, Scale) {
  EXPECT_ERROR(withElement(R"("scale": [{"t": 0, "value": 0}])"), "elements[0].scale[0].value: must be positive");
  EXPECT_ERROR(withElement(R"("scale": [{"t": 0, "value": -1}])"), "elements[0].scale[0].value: must be positive");
  EXPECT_ERROR(withElement(R"("targets": [{"t": 0, "x": 0, "y": 0, "scale": 0}, {"t": 1, "x": 0, "y": 0}])"),
               "elements[0].targets[0].scale: must be positive");
}

TEST(AnimationScriptReader, Targets) {
  EXPECT_ERROR(withElement(R"("targets": [{"t": 0, "x": 0, "y": 0}])"), "elements[0].targets: a guided element needs at least two");
  EXPECT_ERROR(withElement(R"("targets": [{"t": 0.1, "x": 0, "y": 0}, {"t": 1, "x": 0, "y": 0}])"),
               "elements[0].targets[0].t: the first target must be at t = 0");
  EXPECT_ERROR(withElement(R"("targets": [{"t": 0, "x": 0, "y": 0}, {"t": 0.9, "x": 0, "y": 0}])"),
               "elements[0].targets[1].t: the last target must be at t = 1");
  EXPECT_ERROR(withElement(R"("count": 2, "targets": [{"t": 0, "x": 0, "y": 0}, {"t": 1, "x": 0, "y": 0}])"),
               "elements[0].count: a guided element (one with targets) has count 1");
}

TEST(AnimationScriptReader, IdsAndLoops) {
  EXPECT_ERROR(R"({"elements": [{"id": "a", "svg": "a.svg"}, {"id": "a", "svg": "b.svg"}]})",
               "elements[1].id: duplicate id \"a\"");
  // A default id collides with an explicit one too.
  EXPECT_ERROR(R"({"elements": [{"svg": "a.svg"}, {"id": "element-0", "svg": "b.svg"}]})",
               "elements[1].id: duplicate id \"element-0\"");
  const std::string guided = R"("targets": [{"t": 0, "x": 0, "y": 0}, {"t": 1, "x": 0, "y": 0}])";
  EXPECT_ERROR(withElement(guided + R"(, "loop_to": "nobody")"), "elements[0].loop_to: no element has the id \"nobody\"");
  EXPECT_ERROR(withElement(R"("loop_to": "element-0")"), "elements[0].loop_to: only a guided element");
  EXPECT_ERROR(withElement(guided + R"(, "loop_to": 3)"), "elements[0].loop_to: must be a string");
  // Two guided elements trading places (a permutation loop).
  const AnimationScript swap = parse(R"({"elements": [
      {"id": "a", "svg": "a.svg", "targets": [{"t": 0, "x": 0, "y": 0}, {"t": 1, "x": 9, "y": 0}], "loop_to": "b"},
      {"id": "b", "svg": "a.svg", "targets": [{"t": 0, "x": 9, "y": 0}, {"t": 1, "x": 0, "y": 0}], "loop_to": "a"}]})");
  EXPECT_EQ(swap.elements[0].loopTo, "b");
  EXPECT_EQ(swap.elements[1].loopTo, "a");
}

TEST(AnimationScriptReader, LeavesContainer) {
  const std::string guided = R"("targets": [{"t": 0, "x": 0, "y": 0}, {"t": 1, "x": 9, "y": 0}])";
  EXPECT_TRUE(parse(withElement(guided + R"(, "leaves_container": true)")).elements[0].leavesContainer);
  EXPECT_FALSE(parse(withElement(guided)).elements[0].leavesContainer);
  EXPECT_ERROR(withElement(guided + R"(, "leaves_container": 1)"), "elements[0].leaves_container: must be true or false");
  EXPECT_ERROR(withElement(R"("leaves_container": true)"),
               "elements[0].leaves_container: only a guided element (one with targets) can leave the container");
}

TEST(AnimationScriptReader, Orientation) {
  EXPECT_EQ(*parse(withElement(R"("orientation": -45.5)")).elements[0].orientation, -45.5);
  EXPECT_FALSE(parse(withElement(R"("orientation": "random")")).elements[0].orientation);
  EXPECT_FALSE(parse(withElement(R"("orientation": "random")")).elements[0].orientationFromField);
  const AnimationScript field = parse(withElement(R"("orientation": "field")"));
  EXPECT_FALSE(field.elements[0].orientation);
  EXPECT_TRUE(field.elements[0].orientationFromField);
  EXPECT_ERROR(withElement(R"("orientation": "up")"),
               "elements[0].orientation: must be a number (degrees), \"random\" or \"field\"");
  EXPECT_ERROR(withElement(R"("orientation": true)"),
               "elements[0].orientation: must be a number (degrees), \"random\" or \"field\"");
}

}  // namespace
}  // namespace pak
