// Built when CABLEFILM_RENDER is OFF: the result files are written, the film is not.
#include <cstdio>

#include "app/film_pass.h"

namespace cablefilm {

bool RenderFilm(const SceneDef&, const std::vector<FilmRun>&, const FilmRequest&,
                const std::atomic<int>&) {
  std::printf("film: not rendered (this build has no renderer: CABLEFILM_RENDER=OFF)\n");
  return true;
}

}  // namespace cablefilm
