#include "flow_resolve.hpp"

#include "mirror_option.hpp"

namespace pak::cli {

void resolveFlowOptions(FlowArguments& args, const CLI::App& command, const nlohmann::json* config,
                        const std::string& configName) {
  if (config) flowOptions().applyConfigObject(*config, configName, command, args, &args.common.lengths);
  if (!args.mirror.empty()) args.options.mirror = parseMirror(args.mirror);
}

}  // namespace pak::cli
