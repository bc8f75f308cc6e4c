#include "app/output_over_input.h"

#include <filesystem>
#include <system_error>

#include "scene/option_values.h"

namespace cablefilm {

void RefuseOutputOverInput(const std::string& output, const std::vector<std::string>& inputs) {
  if (output.empty() || output == "-") return;
  for (const std::string& input : inputs) {
    std::error_code ec;  // either missing: not the same file
    if (!std::filesystem::equivalent(output, input, ec) || ec) continue;
    Bad("-o: " + Shown(output) + " is the input file " + Shown(input) +
        ": the output would replace it; expected another file");
  }
}

}  // namespace cablefilm
