#include "modules/module_loader.h"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <map>
#include <mutex>
#include <vector>

#include "core/error.h"

namespace cablefilm {
namespace {

std::string DirOf(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? "." : path.substr(0, slash == 0 ? 1 : slash);
}

std::string ProgramPath() {
  std::vector<char> buf(4096);
  const ssize_t n = ::readlink("/proc/self/exe", buf.data(), buf.size() - 1);
  return n > 0 ? std::string(buf.data(), static_cast<std::size_t>(n)) : "";
}

// The file holding this code: the program, or the Python module that links the loader.
std::string ThisObjectPath() {
  Dl_info info{};
  if (::dladdr(reinterpret_cast<void*>(&ProgramPath), &info) && info.dli_fname)
    return info.dli_fname;
  return "";
}

std::vector<std::string> SearchDirs() {
  if (const char* dir = std::getenv("CABLEFILM_MODULE_DIR"); dir && *dir) return {dir};
  std::vector<std::string> dirs;
  const std::string program = ProgramPath(), object = ThisObjectPath();
  if (!object.empty() && object.find('/') != std::string::npos && object != program &&
      object.size() > 3 && object.compare(object.size() - 3, 3, ".so") == 0) {
    // The Python module: built into <build>/python/ (the modules in <build>), installed into
    // <prefix>/lib/python3.X/dist-packages/ (the modules in <prefix>/lib/cablefilm).
    dirs.push_back(DirOf(DirOf(object)));
    dirs.push_back(DirOf(DirOf(DirOf(object))) + "/cablefilm");
  } else if (!program.empty()) {
    dirs.push_back(DirOf(program));
    dirs.push_back(DirOf(program) + "/../lib/cablefilm");
  }
  dirs.push_back(CABLEFILM_MODULE_INSTALL_DIR);  // the installed modules, wherever this is
  return dirs;
}

struct Loaded {
  std::mutex mutex;
  std::map<std::string, const void*> tables;  // by file name
};

}  // namespace

std::string ModuleSearchPath() {
  std::string s;
  for (const std::string& d : SearchDirs()) s += (s.empty() ? "" : ":") + d;
  return s;
}

const void* LoadModuleTable(const std::string& file, const char* entry, const std::string& abi,
                            const std::string& what) {
  static Loaded loaded;
  std::lock_guard<std::mutex> lock(loaded.mutex);
  if (auto it = loaded.tables.find(file); it != loaded.tables.end()) return it->second;
  std::string tried;
  for (const std::string& dir : SearchDirs()) {
    const std::string path = dir + "/" + file;
    if (::access(path.c_str(), F_OK) != 0) {
      tried += "\n  " + path + ": not there";
      continue;
    }
    // Lazy: a function of the module or of its libraries (but those linked "now") is looked up
    // when first called, not all at load: 2 of the 13 ms that loading libnetcdf and HDF5 costs.
    void* handle = ::dlopen(path.c_str(), RTLD_LAZY | RTLD_LOCAL);
    if (!handle) {
      const char* why = ::dlerror();
      throw Error(what + ": cannot load the module " + path + ": " + (why ? why : "dlopen failed"));
    }
    using Entry = const void* (*)();
    auto fn = reinterpret_cast<Entry>(::dlsym(handle, entry));
    if (!fn) throw Error(what + ": the module " + path + " has no entry " + entry);
    const void* table = fn();
    // Every table starts with its build's ModuleAbi().
    const char* its_abi = *static_cast<const char* const*>(table);
    if (abi != its_abi)
      throw Error(what + ": the module " + path + " is from another build (" + its_abi +
                  "; this program is " + abi + "): rebuild or reinstall cablefilm");
    loaded.tables[file] = table;
    return table;
  }
  throw Error(what + ": cannot find the module " + file + " (set CABLEFILM_MODULE_DIR to its "
              "folder); looked for:" + tried);
}

}  // namespace cablefilm
