#pragma once
// The live page's files (src/live/page/), embedded in the binary at build time so the program
// serves its page from any folder, offline, with no CDN.
#include <cstddef>
#include <string>

namespace cablefilm {

struct PageAsset {
  const char* name;       // file name, e.g. "index.html" (served at "/" and "/index.html")
  const char* mime_type;  // e.g. "text/html; charset=utf-8"
  const unsigned char* data;
  std::size_t size;
};

// The asset served at `path` ("/", "/app.js", ...); null if there is none.
const PageAsset* FindPageAsset(const std::string& path);

}  // namespace cablefilm
