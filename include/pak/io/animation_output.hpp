#pragma once
// Writers for rendered animations (thesis 5.6): every output takes the same sequence of
// frames, each a Drawing, so the PNG frames, SVG frames, animated SVG, GIF, video and contact
// sheet all show the same thing. All files are written atomically (temporary file + rename).
#include <optional>
#include <string>
#include <vector>

#include "pak/io/drawing.hpp"
#include "pak/io/png_renderer.hpp"

namespace pak {

struct AnimationOutputOptions {
  double duration = 10.0;  // seconds the whole sequence lasts (one loop)
  bool loop = true;        // play forever (GIF loop count 0, SVG repeatCount="indefinite")
  int width = 600;         // raster outputs: pixels across
  // nullopt: transparent (PNG frames, contact sheet; GIF: one transparent index, so hard
  // edges; video has no alpha and gets white).
  std::optional<Color> background = Color{255, 255, 255, 1.0};
  int svgPrecision = -1;   // SVG decimals; -1: SVG frames as the SVG writer, animated SVG from
                           // the view box size (about 1/10000 of it)
  // SVG frames: > 0 writes outlines as cubic Béziers fitted within this distance (input units),
  // as SvgWriteOptions::curveTolerance. The animated SVG keeps polygons: it interpolates `d`
  // between keyframes, which needs the same points in every frame.
  double svgCurveTolerance = 0.0;
};

// frame-0000.png, frame-0001.png … in `folder` (created if missing).
void writePngFrames(const std::vector<Drawing>& frames, const std::string& folder, const AnimationOutputOptions& = {});
// frame-0000.svg … in `folder`.
void writeSvgFrames(const std::vector<Drawing>& frames, const std::string& folder, const AnimationOutputOptions& = {});
// One SVG that plays in a browser (SMIL). When every frame has the same structure (groups,
// shapes, subpaths and point counts), each shape is one <path> whose `d` is animated through
// the frames; otherwise each frame is a group shown for its time slot.
void writeAnimatedSvg(const std::vector<Drawing>& frames, const std::string& path, const AnimationOutputOptions& = {});
// The same SVG as text; errors name `where`.
std::string animatedSvgText(const std::vector<Drawing>& frames, const std::string& where,
                            const AnimationOutputOptions& = {});
// An animated GIF (libcgif) with one palette for all frames.
void writeGif(const std::vector<Drawing>& frames, const std::string& path, const AnimationOutputOptions& = {});
// Whether the `ffmpeg` program can be run.
bool videoEncoderAvailable();
// Throws InputError unless `path` names a video format writeVideo knows and ffmpeg can be run:
// for checking before a long run.
void checkVideoTarget(const std::string& path);
// MP4 (H.264) or WebM by the file's extension, through the `ffmpeg` program. Throws InputError
// when ffmpeg is missing or fails.
void writeVideo(const std::vector<Drawing>& frames, const std::string& path, const AnimationOutputOptions& = {});
// The given frames side by side in rows of `columns`, each captioned (e.g. "t = 0.25"), like
// the thesis's figures. `captions` is empty or one per frame.
void writeContactSheet(const std::vector<Drawing>& frames, const std::vector<std::string>& captions,
                       const std::string& path, int columns = 5, const AnimationOutputOptions& = {});

}  // namespace pak
