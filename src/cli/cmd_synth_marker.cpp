// armmimic-cli synth marker OUTDIR: the model joint of thesis chapter 4 rendered in 3D, with a
// zero-pose reference and the ground truth.
#include <iostream>

#include "args.h"
#include "armmimic/synth/marker_rig.h"
#include "armmimic/synth/marker_scene.h"
#include "flag_for_key.h"
#include "synth_commands.h"

namespace armmimic::cli {

namespace {

// --renderer rig: the rig comes from --set and the seed, so the first renderer's scene flags
// have no meaning here.
int WriteRig(const ArgParser& p, const synth::MarkerSceneOptions& o, synth::MarkerRigOptions rig,
             const std::string& outdir, const GlobalOptions& global) {
  for (const char* flag :
       {"--noise", "--background", "--lighting", "--clutter", "--camera", "--fov"}) {
    if (p.Given(flag)) {
      return p.UsageError(std::string(flag) + " does not apply to --renderer rig (--set chooses " +
                          "the conditions)");
    }
  }
  rig.seed = o.seed;
  rig.size = o.size;
  rig.views = o.views;
  rig.max_yaw_deg = p.Given("--max-yaw") ? o.max_yaw_deg : 60;
  rig.max_bend_deg = o.max_bend_deg;
  if (Status st = rig.Check(); !st.ok()) return p.UsageError(Worded(st));
  if (const int code = WriteSceneWithProgress(
          "marker", rig.views, global,
          [&](const auto& progress, const auto* cancel) {
            return synth::WriteMarkerRigScene(rig, outdir, progress, cancel);
          },
          outdir + " has no truth.tsv (not a whole scene)");
      code != kExitOk) {
    return code;
  }
  if (!global.quiet) {
    std::cout << "wrote " << outdir << "/reference.png, " << rig.views << " views in " << outdir
              << "/views and " << outdir << "/truth.tsv (rig renderer, " << rig.set << " set)\n";
  }
  return kExitOk;
}

}  // namespace

int RunSynthMarker(const std::vector<std::string>& args, const GlobalOptions& global) {
  synth::MarkerSceneOptions o;
  std::vector<std::string> outdir;
  ArgParser p(
      "synth marker",
      "  armmimic-cli synth marker OUTDIR [--seed N] [--size WxH] [--views N] [--max-yaw D]\n"
      "      [--max-bend D] [--noise S] [--background plain|gradient|texture|room|simple|mixed]\n"
      "      [--lighting normal|bright|dim|side|shadow|mixed] [--clutter K]\n"
      "      [--camera perspective|orthographic] [--fov D]\n"
      "  armmimic-cli synth marker OUTDIR --renderer rig [--set easy|medium|hard] [--seed N]\n"
      "      [--size WxH] [--views N] [--max-yaw D] [--max-bend D]",
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
      "The same seed and options give the same files.\n"
      "--renderer rig draws the views with a second, independent ray tracer: each seed draws\n"
      "its own rig within the ranges of --set (joint radius, marker size and placement, camera\n"
      "height, tilt and aim, lens distortion, specular highlights, blur, a wall that takes the\n"
      "joint's shadow; hard adds dark blobs). truth.tsv's meta line records the rig (fov_deg\n"
      "among it, for analyze --fov).");
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
  std::string renderer = "scene";
  synth::MarkerRigOptions rig;
  p.String("--renderer", &renderer, "KIND",
           "scene (default: the renderer above) or rig (the independent one, see below)");
  p.String("--set", &rig.set, "SET", "with --renderer rig: easy, medium (default) or hard");
  if (auto code = p.Parse(args)) return *code;
  if (renderer == "rig") return WriteRig(p, o, rig, outdir[0], global);
  if (renderer != "scene") {
    return p.UsageError("--renderer: '" + renderer + "' is not one of scene, rig");
  }
  if (p.Given("--set")) return p.UsageError("--set needs --renderer rig");
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
