// The AnimationPak animation file (JSON; format and example in docs/animation-format.md).
// Strict on purpose: an unknown key is an error rather than ignored, since a misspelt
// "rotaton" would otherwise silently animate nothing. Every error names the file and the JSON
// path of the offending value ("anim.json: elements[2].rotation[1].t: …").
#include "pak/io/animation_script_reader.hpp"

#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "pak/error.hpp"
#include "pak/limits.hpp"
#include "pak/io/json_syntax_error.hpp"
#include "pak/io/text_file.hpp"

namespace pak {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;  // file order, so the first typo reported is the first written

class Reader {
 public:
  explicit Reader(std::string where) : where_(std::move(where)) {}

  // `path`: the field, as in "elements[2].rotation[1]": where in the file the error is.
  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw InputError(path.empty() ? where_ : where_ + ": " + path, what);
  }

  void requireObject(const Json& value, const std::string& path, const std::string& what) const {
    if (!value.is_object()) fail(path, "must be " + what);
  }

  // Every key of `object` must be one of `known`.
  void checkKeys(const Json& object, const std::string& path, std::initializer_list<const char*> known) const {
    for (const auto& [key, value] : object.items()) {
      bool found = false;
      for (const char* k : known) found = found || key == k;
      if (found) continue;
      std::string list;
      for (const char* k : known) list += (list.empty() ? "" : ", ") + std::string(k);
      fail(path, "unknown key \"" + key + "\" (known keys: " + list + ")");
    }
  }

  double number(const Json& value, const std::string& path) const {
    if (!value.is_number()) fail(path, "must be a number");
    const double x = value.get<double>();
    if (!std::isfinite(x)) fail(path, "must be a finite number");
    return x;
  }

  // A number within [-limit, limit], the limit named in the message.
  double bounded(const Json& value, const std::string& path, double limit) const {
    const double x = number(value, path);
    if (std::abs(x) > limit) fail(path, "must be within ±" + messageNumber(limit) + " (got " + messageNumber(x) + ")");
    return x;
  }

  int integer(const Json& value, const std::string& path, int low, int high) const {
    const double x = number(value, path);
    if (x != std::floor(x)) fail(path, "must be a whole number");
    if (x < low || x > high)
      fail(path, "must be within [" + std::to_string(low) + ", " + std::to_string(high) + "] (got " + value.dump() + ")");
    return static_cast<int>(x);
  }

  std::string string(const Json& value, const std::string& path) const {
    if (!value.is_string()) fail(path, "must be a string");
    return value.get<std::string>();
  }

  const Json& member(const Json& object, const std::string& path, const char* key) const {
    if (!object.contains(key)) fail(path, std::string("missing \"") + key + "\"");
    return object.at(key);
  }

  // An array of key objects with strictly increasing t in [0, 1]; `read` turns each one
  // (already checked for t) into the key type.
  template <class Key, class Read>
  std::vector<Key> keys(const Json& value, const std::string& path, Read read) const {
    if (!value.is_array()) fail(path, "must be an array of keys ({\"t\": …, …})");
    std::vector<Key> result;
    for (std::size_t i = 0; i < value.size(); ++i) {
      const std::string at = path + "[" + std::to_string(i) + "]";
      const Json& key = value[i];
      requireObject(key, at, "an object with \"t\"");
      const double t = number(member(key, at, "t"), at + ".t");
      if (t < 0.0 || t > 1.0) fail(at + ".t", "t must be within [0, 1]");
      if (!result.empty() && t <= result.back().t)
        fail(at + ".t", "keys must be sorted by t, each later than the one before");
      result.push_back(read(key, at, t));
    }
    return result;
  }

  std::vector<ScalarKey> scalarKeys(const Json& value, const std::string& path, bool positive, double limit) const {
    return keys<ScalarKey>(value, path, [&](const Json& key, const std::string& at, double t) {
      checkKeys(key, at, {"t", "value"});
      const double v = bounded(member(key, at, "value"), at + ".value", limit);
      if (positive && v <= 0.0) fail(at + ".value", "must be positive");
      return ScalarKey{t, v};
    });
  }

  std::vector<PointKey> pointKeys(const Json& value, const std::string& path, const char* xName, const char* yName) const {
    return keys<PointKey>(value, path, [&](const Json& key, const std::string& at, double t) {
      checkKeys(key, at, {"t", xName, yName});
      return PointKey{t, {bounded(member(key, at, xName), at + "." + xName, limits::kMaxAnimationCoordinate),
                          bounded(member(key, at, yName), at + "." + yName, limits::kMaxAnimationCoordinate)}};
    });
  }

  std::vector<GuideTarget> targets(const Json& value, const std::string& path) const {
    std::vector<GuideTarget> result = keys<GuideTarget>(value, path, [&](const Json& key, const std::string& at, double t) {
      checkKeys(key, at, {"t", "x", "y", "scale", "rotation"});
      GuideTarget target;
      target.t = t;
      target.position = {bounded(member(key, at, "x"), at + ".x", limits::kMaxAnimationCoordinate),
                         bounded(member(key, at, "y"), at + ".y", limits::kMaxAnimationCoordinate)};
      if (key.contains("scale")) {
        target.scale = bounded(key["scale"], at + ".scale", limits::kMaxAnimationScale);
        if (*target.scale <= 0.0) fail(at + ".scale", "must be positive");
      }
      if (key.contains("rotation")) target.rotation = bounded(key["rotation"], at + ".rotation", limits::kMaxDegrees);
      return target;
    });
    if (result.size() < 2) fail(path, "a guided element needs at least two targets");
    if (result.front().t != 0.0) fail(path + "[0].t", "the first target must be at t = 0");
    if (result.back().t != 1.0) fail(path + "[" + std::to_string(result.size() - 1) + "].t", "the last target must be at t = 1");
    return result;
  }

  AnimatedElementSpec element(const Json& value, const std::string& path, std::size_t index, const std::string& folder) const {
    requireObject(value, path, "an object");
    checkKeys(value, path,
              {"id", "svg", "count", "rotation", "scale", "translation", "handles", "orientation", "targets", "loop_to",
               "leaves_container"});
    AnimatedElementSpec spec;
    spec.id = "element-" + std::to_string(index);
    if (value.contains("id")) {
      spec.id = string(value["id"], path + ".id");
      if (spec.id.empty()) fail(path + ".id", "must not be empty");
    }
    const std::string svg = string(member(value, path, "svg"), path + ".svg");
    if (svg.empty()) fail(path + ".svg", "must name an element file");
    const fs::path file(svg);
    spec.svg = file.is_absolute() || folder.empty() ? svg : (fs::path(folder) / file).lexically_normal().string();

    if (value.contains("count")) spec.count = integer(value["count"], path + ".count", 1, limits::kMaxElementCopies);
    if (value.contains("rotation"))
      spec.animation.rotation = scalarKeys(value["rotation"], path + ".rotation", false, limits::kMaxDegrees);
    if (value.contains("scale")) spec.animation.scale = scalarKeys(value["scale"], path + ".scale", true, limits::kMaxAnimationScale);
    if (value.contains("translation"))
      spec.animation.translation = pointKeys(value["translation"], path + ".translation", "x", "y");
    if (value.contains("handles")) {
      const Json& handles = value["handles"];
      requireObject(handles, path + ".handles", "an object of handle name → keys");
      for (const auto& [name, track] : handles.items()) {
        if (name.empty()) fail(path + ".handles", "a handle name must not be empty");
        spec.animation.handles.push_back({name, pointKeys(track, path + ".handles." + name, "dx", "dy")});
      }
    }
    if (value.contains("orientation")) {
      const Json& orientation = value["orientation"];
      if (orientation.is_string()) {
        const std::string kind = orientation.get<std::string>();
        if (kind != "random" && kind != "field")
          fail(path + ".orientation", "must be a number (degrees), \"random\" or \"field\"");
        spec.orientation = std::nullopt;
        spec.orientationFromField = kind == "field";
      } else if (orientation.is_number()) {
        spec.orientation = bounded(orientation, path + ".orientation", limits::kMaxDegrees);
      } else {
        fail(path + ".orientation", "must be a number (degrees), \"random\" or \"field\"");
      }
    }
    if (value.contains("targets")) {
      spec.targets = targets(value["targets"], path + ".targets");
      if (spec.count != 1) fail(path + ".count", "a guided element (one with targets) has count 1");
    }
    if (value.contains("loop_to")) {
      spec.loopTo = string(value["loop_to"], path + ".loop_to");
      if (spec.targets.empty()) fail(path + ".loop_to", "only a guided element (one with targets) can loop to another");
      if (spec.loopTo.empty()) fail(path + ".loop_to", "must name an element id");
    }
    if (value.contains("leaves_container")) {
      if (!value["leaves_container"].is_boolean()) fail(path + ".leaves_container", "must be true or false");
      spec.leavesContainer = value["leaves_container"].get<bool>();
      if (spec.leavesContainer && spec.targets.empty())
        fail(path + ".leaves_container", "only a guided element (one with targets) can leave the container");
    }
    return spec;
  }

  AnimationScript script(const std::string& text, const std::string& folder) const {
    Json root;
    try {
      root = Json::parse(text);
    } catch (const Json::exception& error) {  // syntax, or a number too large for a double
      throw jsonSyntaxError(where_, error.what());
    }
    requireObject(root, "", "a JSON object (the animation file's top level)");
    checkKeys(root, "", {"slices", "frames", "loop", "duration", "elements"});

    AnimationScript script;
    script.source = where_;
    if (root.contains("slices")) script.slices = integer(root["slices"], "slices", 2, limits::kMaxSlices);
    if (root.contains("frames")) script.frames = integer(root["frames"], "frames", 1, limits::kMaxFrames);
    if (root.contains("loop")) {
      if (!root["loop"].is_boolean()) fail("loop", "must be true or false");
      script.loop = root["loop"].get<bool>();
    }
    if (root.contains("duration")) {
      script.duration = bounded(root["duration"], "duration", limits::kMaxLoopSeconds);
      if (script.duration <= 0.0) fail("duration", "must be positive (seconds)");
    }
    const Json& elements = member(root, "", "elements");
    if (!elements.is_array()) fail("elements", "must be an array");
    if (elements.empty()) fail("elements", "at least one element is needed");

    std::map<std::string, std::size_t> ids;
    for (std::size_t i = 0; i < elements.size(); ++i) {
      const std::string path = "elements[" + std::to_string(i) + "]";
      AnimatedElementSpec spec = element(elements[i], path, i, folder);
      const auto [at, inserted] = ids.emplace(spec.id, i);
      if (!inserted)
        fail(path + ".id", "duplicate id \"" + spec.id + "\" (also elements[" + std::to_string(at->second) + "])");
      script.elements.push_back(std::move(spec));
    }
    for (std::size_t i = 0; i < script.elements.size(); ++i) {
      const std::string& loopTo = script.elements[i].loopTo;
      if (!loopTo.empty() && !ids.count(loopTo))
        fail("elements[" + std::to_string(i) + "].loop_to", "no element has the id \"" + loopTo + "\"");
    }
    return script;
  }

 private:
  std::string where_;
};

}  // namespace

AnimationScript parseAnimationScript(const std::string& json, const std::string& where, const std::string& folder) {
  return Reader(where).script(json, folder);
}

AnimationScript readAnimationScript(const std::string& path) {
  return parseAnimationScript(readTextFile(path), path, fs::path(path).parent_path().string());
}

}  // namespace pak
