#pragma once
// The frame layouts' shared measures, in design pixels (times the frame's scale k: 1 at
// 1920x1080): frame_layout.cpp (the picture in the plane) and space_layout.cpp (in space).
namespace cablefilm::layout {

constexpr float kMargin = 24, kGap = 16;                            // frame edge; between panels
constexpr float kPlotLeft = 86, kPlotRight = 26, kPlotBottom = 62;  // tick labels, axis titles
constexpr float kCableLeft = 80;    // a to-scale panel's left: its y tick labels and title
constexpr float kCableRight = 172;  // the colour bar with its ticks and caption
constexpr float kColorBarLeft = 128, kColorBarRight = 106;  // the bar, from the panel's right
constexpr float kColorBarCaption = 20;                      // its caption, from the panel's right

}  // namespace cablefilm::layout
