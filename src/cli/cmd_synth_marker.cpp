// armmimic-cli synth marker OUTDIR: the model joint of thesis chapter 4 rendered in 3D, with a
// zero-pose reference and the ground truth.
#include <iostream>

#include "args.h"
#include "armmimic/synth/marker_scene.h"
#include "flag_for_key.h"
#include "synth_commands.h"

namespace armmimic::cli {

int RunSynthMarker(const std::vector<std::string>& args, const GlobalOptions& global) {
  synth::MarkerSceneOptions o;
  std::vector<std::string> outdir;
  ArgParser p(
      "synth marker",
      "  armmimic-cli synth marker OUTDIR [--seed N] [--size WxH] [--views N] [--max-yaw D]\n"
      "      [--max-bend D] [--noise S] [--background plain|gradient|texture|room|simple|mixed]\n"
      "      [--lighting normal|bright|dim|side|shadow|mixed] [--clutter K]\n"
      "      [--camera perspective|orthographic] [--fov D]",
      "Ray casts the thesis' model joint (chapter 4): two equal Lambertian-shaded cylinders, the\n"
      "lower one upright and turning about its axis (yaw), the upper one bending at the pivot;\n"
      "two black markers on the lower part's curved surface at equal angles either side of the\n"
      "front, one on the front of the upper part at the same distance from the pivot. A level\n"
      "pinhole camera looks at it (--camera orthographic: the flat model, a parallel\n"
      "projection). Writes OUTDIR/reference.png (zero yaw, zero bend), OUTDIR/views/view_NNN.png\n"
      "and OUTDIR/truth.tsv (yaw and bend from the model, a `file` column, the signed yaw, the\n"
      "projected marker centres, and `readable` = 1 where a lower marker faces the camera within\n"
      "75 degrees; per marker in upper/left/right_readable). Analyse with:\n"
      "  armmimic-cli analyze OUTDIR/views -o angles.tsv --engine marker "
      "--reference OUTDIR/reference.png\n"
      "The same seed and options give the same files.");
  p.Positionals(&outdir, "OUTDIR", 1, 1);
  p.Custom("--seed", "N", "random seed for the scene, the poses and the noise (default 1)",
           [&o](const std::string& v) { return ParseSeedArg(v, &o.seed); });
  p.Custom("--size", "WxH", "image size (default 320x240; at least 160x120, 4:3 or wider)",
           [&o](const std::string& v) { return ParseSizeArg(v, &o.size); });
  p.Int("--views", &o.views, "N", "images besides the reference (default 48)", 1, 100000);
  p.Double("--max-yaw", &o.max_yaw_deg, "D",
           "yaw uniform in [-D, D] degrees, up to 180 (default 45)");
  p.Double("--max-bend", &o.max_bend_deg, "D", "bend uniform in [-D, D] degrees (default 60)");
  p.Double("--noise", &o.noise_sigma, "S", "Gaussian sensor noise sigma, grey levels (default 2)");
  p.String("--background", &o.background, "KIND",
           "plain, gradient, texture, room, simple (plain or gradient) or mixed (default: any, "
           "picked by the seed)");
  p.String("--lighting", &o.lighting, "KIND",
           "normal, bright, dim, side, shadow (a dark shadow on the wall, thesis Fig. 4-10) or "
           "mixed (default: picked by the seed)");
  p.Int("--clutter", &o.clutter, "K",
        "dark marker-like blobs on the background, every third beside the lower markers "
        "(default 0)",
        0, 100);
  p.String("--camera", &o.camera.projection, "KIND",
           "perspective (default) or orthographic (the flat model, to compare)");
  p.Double("--fov", &o.camera.fov_deg, "D",
           "the perspective camera's horizontal field of view, degrees (default 60)");
  if (auto code = p.Parse(args)) return *code;
  if (Status st = o.Check(); !st.ok()) return p.UsageError(Worded(st));

  if (const int code = WriteSceneWithProgress(
          "marker", o.views, global,
          [&](const auto& progress, const auto* cancel) {
            return synth::WriteMarkerScene(o, outdir[0], progress, cancel);
          },
          outdir[0] + " has no truth.tsv (not a whole scene)");
      code != kExitOk) {
    return code;
  }
  if (!global.quiet) {
    std::cout << "wrote " << outdir[0] << "/reference.png, " << o.views << " views in " << outdir[0]
              << "/views and " << outdir[0] << "/truth.tsv\n";
  }
  return kExitOk;
}

}  // namespace armmimic::cli
