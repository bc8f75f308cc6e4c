#pragma once
// Opens one of the program's modules (module_api.h) the first time it is needed and returns
// the table its entry function gives. Looked for in $CABLEFILM_MODULE_DIR when set, else
// beside the program (the build tree) and in <program>/../lib/cablefilm (installed), or, for
// the Python module, in the folder above its own (<build>/python/..); last in the install
// prefix's lib/cablefilm. Thread-safe; a module stays loaded. Throws Error naming the module, where it was looked for and why it
// was refused (not found, dlerror's message, another build).
#include <string>

namespace cablefilm {

const void* LoadModuleTable(const std::string& file, const char* entry, const std::string& abi,
                            const std::string& what);

// The folders searched, in order.
std::string ModuleSearchPath();

}  // namespace cablefilm
