// Private: one limb of the straight joint in the reference, fitted over every row that shows it
// (docs/marker.md, "Calibration", step 2). An upright cylinder's shading depends on the angle
// about its axis only, so next to its limb every row shows the same grey levels, shifted with
// the limb; the wall beside it differs from row to row (a shadow, a poster, a gradient). One
// fit over all rows (the surface's shading shared, each row's wall its own) pins the limb where
// the wall differs from the surface, which a single row's profile cannot: there a limb as dark
// as the wall and a surface that darkens ever faster towards it look alike a pixel further out.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

namespace armmimic::internal {

struct LimbFit {
  bool ok = false;
  double x = 0;     // the limb's column at row y_ref
  double lean = 0;  // columns per row (the camera's tilt makes verticals lean)
  double rms = 0;   // grey levels, the fit's misfit per pixel
  int groups = 0;   // row groups used
};

// Fits the limb on one side (`inside` +1: the joint lies right of it, -1: left) over `rows` of
// `gray`, starting near column `x_guess` at row `y_ref`, searched within `range` columns.
LimbFit FitLimb(const cv::Mat& gray, const std::vector<int>& rows, double x_guess, double y_ref,
                int inside, double range);

}  // namespace armmimic::internal
