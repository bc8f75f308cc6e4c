#pragma once
// The header above the panels: the title and a dim subtitle on the left (after an optional
// status in the accent colour), the time in large type on the right with a dim note under it
// and an optional progress bar beside the note.
#include <string>

#include "view/painter.h"
#include "view/theme.h"

namespace cablefilm {

struct HeaderInput {
  std::string title;
  std::string status;    // e.g. "live · 1.0x": a dot and this, before the subtitle; "" = none
  std::string subtitle;  // dim, under the title
  std::string time;      // e.g. "t = 12.34 s", top right
  std::string note;      // dim, under the time
  double progress = -1;  // fraction [0, 1] of a bar left of the note; < 0 = no bar
};

// Height of the header from the frame's top [px] (the panels start there).
float HeaderHeight(float k);
// Draws the header across a frame `width` pixels wide.
void DrawHeader(Painter& p, float width, const HeaderInput& in, const Theme& th);

}  // namespace cablefilm
