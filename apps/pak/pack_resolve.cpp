#include "pack_resolve.hpp"

#include <cmath>
#include <cstdio>
#include <set>

#include "pak/error.hpp"
#include "pak/repulsion/orientation.hpp"
#include "pak/repulsion/repulsion_presets.hpp"

namespace pak::cli {
namespace {

// "W,H" (input units) for --tile.
Vec2 parseTileSize(const std::string& text) {
  double w = 0.0, h = 0.0;
  char extra = 0;
  if (std::sscanf(text.c_str(), " %lf , %lf %c", &w, &h, &extra) != 2 || !(w > 0.0 && h > 0.0) || !std::isfinite(w) ||
      !std::isfinite(h))
    throw InputError("--tile", "expects W,H with two positive numbers, got \"" + text + "\"");
  return {w, h};
}

}  // namespace

// The config may name the preset, so it is read first; the preset then sets the strengths and
// stopping rule that neither the config nor a flag gives; last, the options given as text are
// parsed.
void resolvePackOptions(PackArguments& args, const CLI::App& command, const nlohmann::json* config,
                        const std::string& configName) {
  const OptionTable<PackArguments>& table = packOptions();
  std::set<std::string> configured;
  if (config) configured = table.applyConfigObject(*config, configName, command, args, &args.common.lengths);
  if (args.rigid && !args.preset.empty() && args.preset != "rigid")
    throw InputError("--rigid", "conflicts with --preset " + args.preset);
  if (args.rigid) args.preset = "rigid";
  if (!args.preset.empty()) {
    PackArguments preset = args;
    applyRepulsionPreset(args.preset, preset.options);
    table.copyUnless(args, preset, [&](const Option<PackArguments>& o) {
      return table.given(command, o) || configured.count(o.name) > 0;
    });
  }
  // A field given alone asks for the field.
  if (command.count("--orientation-field") > 0 && command.count("--orientation") == 0 && args.orientation == "random")
    args.orientation = "field";
  args.options.orientation.mode = parseOrientationMode(args.orientation);
  args.options.orientation.field = parseOrientationField(args.orientationField);
  if (!args.tile.empty()) args.options.tiling.size = parseTileSize(args.tile);
}

}  // namespace pak::cli
