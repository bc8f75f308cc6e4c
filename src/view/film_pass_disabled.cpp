// Built when CABLEFILM_RENDER is OFF: the result files are written, the pictures are not.
#include <cstdio>

#include "view/film_pass.h"
#include "view/max_tension_figure.h"

namespace cablefilm {

PictureReport WriteMaxTensionFigure(const SceneDef&, const std::vector<RowMaxima>&,
                                    const std::string&, bool complete, const std::string&) {
  std::printf("%s: not drawn (this build has no renderer: CABLEFILM_RENDER=OFF)\n",
              complete ? "max_tension.png" : "max_tension.partial.png");
  return {};
}

PictureReport WriteMaxTensionFigure(const SceneDef&, const std::vector<const Run*>&,
                                    const std::string&, bool complete) {
  std::printf("%s: not drawn (this build has no renderer: CABLEFILM_RENDER=OFF)\n",
              complete ? "max_tension.png" : "max_tension.partial.png");
  return {};
}

bool RenderFilm(const SceneDef&, const std::vector<const Run*>&, const FilmRequest&,
                const std::atomic<int>&, PictureReport*) {
  std::printf("film: not rendered (this build has no renderer: CABLEFILM_RENDER=OFF)\n");
  return true;
}

}  // namespace cablefilm
