// The film a front end asks for, from its settings: built with and without the renderer.
#include "view/film_pass.h"

namespace cablefilm {

FilmRequest MakeFilmRequest(const FilmSettings& s, const std::string& out_dir,
                            const std::string& shader_dir) {
  FilmRequest r;
  r.out_dir = out_dir;
  r.frames = s.frames;
  r.width = s.look.width;
  r.height = s.look.height;
  r.fps = s.look.fps;
  r.speed = s.look.speed;
  r.crf = s.look.crf;
  r.colormap = s.look.colormap;
  r.tension_min = s.look.tension_min;
  r.tension_max = s.look.tension_max;
  r.view = s.look.view;
  r.window = s.look.window;
  r.shader_dir = shader_dir;
  return r;
}

}  // namespace cablefilm
