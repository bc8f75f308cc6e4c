#pragma once
// A command's `-o FILE` must not name one of its inputs, however it is spelled (./X.txt for
// X.txt, a symbolic or hard link): the output would replace what it was made from.
#include <string>
#include <vector>

namespace cablefilm {

// Throws UsageError naming `output` and the input it is when it is one of `inputs` (both
// existing, the same file). An empty `output` or "-" (standard output) is none.
void RefuseOutputOverInput(const std::string& output, const std::vector<std::string>& inputs);

}  // namespace cablefilm
