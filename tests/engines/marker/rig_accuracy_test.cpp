// Accuracy of the marker-joint engine on views of the second, independent renderer (`synth
// marker --renderer rig`): each seed draws its own rig (joint radius, marker size and
// placement, camera height, tilt and aim, lens distortion, specular highlights, blur), so the
// engine meets geometry it was not drawn for. The engine is told the rig's field of view, as an
// operator who knows the lens would. Targets (issue 27): yaw and bend mean errors <= 1 degree
// (<= 1.5 for the hard set's yaw), and no answered signed yaw more than 5 degrees off: a sign
// the engine cannot tell is nan. scripts/marker-eval.sh (MARKER_EVAL_MODE=renderers) measures
// the same on the held-out seeds. The answered share asserted here is what the engine reaches
// today on these rigs (docs/marker.md, "Two renderers"): a view read from one lower marker is
// lost when the reference cuts a marker at a limb or shows its two lower markers unequal (the
// calibration's alpha may then be degrees off), as on seeds 502, 505, 602 and 207.
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/angles.h"
#include "armmimic/engines/engine.h"
#include "armmimic/synth/marker_rig.h"
#include "marker/rig_run.h"

namespace armmimic {
namespace {

TEST(MarkerRigAccuracy, EasyRigs) {
  RigTally t;
  for (uint64_t seed : {401, 402, 403}) RunRig("easy", seed, 5, &t);
  EXPECT_GE(t.ok, t.views - 1) << t.log;
  EXPECT_LE(t.yaw_mae(), 1.0) << t.log;
  EXPECT_LE(t.bend_mae(), 1.0) << t.log;
  EXPECT_GE(t.bends, t.ok / 2) << t.log;
  EXPECT_EQ(t.signed_off, 0) << t.log;
}

TEST(MarkerRigAccuracy, MediumRigs) {
  RigTally t;
  for (uint64_t seed : {501, 503, 505}) RunRig("medium", seed, 5, &t);
  // 27 of 28 are asked for (docs/marker.md: not yet); 505's reference cuts a lower marker.
  EXPECT_GE(t.ok, t.views - 4) << t.log;
  EXPECT_LE(t.yaw_mae(), 1.0) << t.log;
  EXPECT_LE(t.bend_mae(), 1.0) << t.log;
  EXPECT_EQ(t.signed_off, 0) << t.log;
}

// Tuning rigs of the hard set where wall blobs once calibrated the engine (seed 207: a
// symmetric triple of blobs beside the joint put its "markers" 0.7 radii from the pivot, and
// every view was lost or 20-100 degrees off; its reference cuts a lower marker, so only its view
// with both lower markers is read now) and where a single lower marker's side rests on the upper
// part's silhouette (211, 212: only one side's bend puts the upper part where the image shows
// it). Since the limbs are fitted over all their rows (docs/marker.md, "Calibration"), two of
// 212's single-marker views are lost as "it could be either" (its alpha moved from 1.1 degrees
// under the truth to 1.0 over it; the right side's upper marker is no longer found and the wrong
// side's shows too little of the upper part's silhouette to decide): 6 of 12 are answered.
TEST(MarkerRigAccuracy, WallBlobsAndOneMarker) {
  RigTally t;
  for (uint64_t seed : {207, 211, 212}) RunRig("hard", seed, 4, &t);
  EXPECT_GE(t.ok, t.views - 6) << t.log;
  EXPECT_LE(t.yaw_max, 5) << t.log;
  EXPECT_LE(t.yaw_mae(), 1.5) << t.log;
  EXPECT_LE(t.bend_mae(), 1.5) << t.log;
  EXPECT_EQ(t.signed_off, 0) << t.log;
}

// A rig whose reference misleads the calibration (seed 502: a faint limb beside one lower marker
// while the other sits at the far limb; alpha 11 degrees off). Its views read from one lower
// marker were 10-13 degrees off; they are lost now, and no answer is more than 5 degrees off.
TEST(MarkerRigAccuracy, UnsureReferenceLosesSingleMarkerViews) {
  RigTally t;
  RunRig("medium", 502, 5, &t);
  EXPECT_GE(t.ok, 2) << t.log;
  EXPECT_LE(t.yaw_max, 5) << t.log;
  EXPECT_EQ(t.signed_off, 0) << t.log;
}

// Rigs whose silhouette the steps placed a pixel off (seed 12: a limb about as dark as the wall
// beside it, the fit of one band's profile a pixel outside it; alpha was 1.1 degrees off, every
// yaw 0.6-1.0) and whose bent upper part's shadow moved one band's step in a view (medium 118:
// the silhouette tracked 1.4 pixels aside, single-marker yaws 2.3-3.7 degrees off). The limbs
// fitted over all their rows, and the silhouette's shift taken from the edges most of the bands
// agree on, read both within a degree.
TEST(MarkerRigAccuracy, LimbsFittedOverAllRowsAndShiftsAgreedOn) {
  RigTally t;
  RunRig("easy", 12, 4, &t);
  RunRig("medium", 118, 4, &t);
  EXPECT_GE(t.ok, t.views - 1) << t.log;
  EXPECT_LE(t.yaw_max, 1.0) << t.log;
  EXPECT_LE(t.yaw_mae(), 0.5) << t.log;
  EXPECT_EQ(t.signed_off, 0) << t.log;
}

// Rigs whose lower part ends within the first half of the band below the markers (validation
// seeds medium 132 and 155): the band's median level was the wall's, no row was kept and the
// reference was refused ("too few rows beside its markers"). The part's end found as the split
// of two levels keeps the rows above it.
TEST(MarkerRigAccuracy, APartEndingSoonBelowTheMarkers) {
  RigTally t;
  RunRig("medium", 132, 4, &t);
  RunRig("medium", 155, 4, &t);
  EXPECT_GE(t.ok, t.views - 1) << t.log;
  EXPECT_LE(t.yaw_mae(), 1.0) << t.log;
  EXPECT_LE(t.yaw_max, 2.0) << t.log;
  EXPECT_EQ(t.signed_off, 0) << t.log;
}

// A rig whose first calibration fitted neither limb within reach of its steps (hard seed 217: one
// bend 42 degrees off). That calibration is passed over for the next attempt, whose silhouette a
// limb fit bears out (its alpha still 3.8 degrees off: bends 1-3 degrees off, yaws up to 3.6).
TEST(MarkerRigAccuracy, ACalibrationNoLimbBearsOutIsPassedOver) {
  RigTally t;
  RunRig("hard", 217, 4, &t);
  EXPECT_GE(t.ok, t.views - 1) << t.log;
  EXPECT_LE(t.bend_max, 5) << t.log;
  EXPECT_LE(t.yaw_max, 5) << t.log;
  EXPECT_EQ(t.signed_off, 0) << t.log;
}

// A view whose bands show a steeper step three pixels beside the limb's own (easy seed 46, its
// upper part bent 50 degrees): the silhouette was tracked 3 pixels aside and a single lower
// marker's yaw read 6 degrees off. The step nearest to the reference's is taken.
TEST(MarkerRigAccuracy, TheLimbsOwnStepIsTracked) {
  RigTally t;
  RunRig("easy", 46, 4, &t);
  EXPECT_GE(t.ok, t.views - 1) << t.log;
  EXPECT_LE(t.yaw_max, 2) << t.log;
  EXPECT_EQ(t.signed_off, 0) << t.log;
}

// Rigs seen from aside with a lower marker near a limb whose step no band tracks (tuning seed
// medium 112, validation seeds medium 144 and 160): the markers' symmetry placed that limb 45 px
// out on the wall, the reference was refused or calibrated with a marker cut. The step the
// first silhouette found is tried after the symmetry, kept when both limbs fit it, and sizes no
// single lower marker (its single-marker yaws were 3-5 degrees off): views read from both lower
// markers are answered.
TEST(MarkerRigAccuracy, AFaintLimbBesideALowerMarker) {
  RigTally t;
  RunRig("medium", 112, 4, &t);
  RunRig("medium", 144, 4, &t);
  RunRig("medium", 160, 4, &t);
  EXPECT_GE(t.ok, 5) << t.log;
  EXPECT_LE(t.yaw_max, 1.5) << t.log;
  EXPECT_LE(t.yaw_mae(), 1.0) << t.log;
  EXPECT_EQ(t.signed_off, 0) << t.log;
}

// Views near zero yaw whose two lower markers disagree by 1.6-3 degrees, read through references
// too unsure to size one marker alone (tuning seed easy 13; validation seeds medium 160, one of
// whose lower markers lies at the limb, and hard 240, alpha 9 degrees off): they were lost. Near
// zero a view looks like the reference and the pair's errors stay small: within 12 degrees of
// zero such a pair may disagree by 2.5 degrees more, and is answered within 2.4 degrees.
TEST(MarkerRigAccuracy, NearZeroPairsOfUnsureReferences) {
  RigTally t;
  RunRig("easy", 13, 4, &t);
  RunRig("medium", 160, 4, &t);
  RunRig("hard", 240, 4, &t);
  EXPECT_GE(t.ok, 5) << t.log;
  EXPECT_LE(t.yaw_max, 3) << t.log;
  EXPECT_LE(t.yaw_mae(), 1.5) << t.log;
  EXPECT_EQ(t.signed_off, 0) << t.log;
}

// One lower marker that could be either, the upper marker found for neither side, and both sides
// turning the joint as far (medium 126, view 2: yaw -45.4, the marker near the front between
// where the two sides put it): the size is read and the sign is nan, not guessed (the view was
// lost before).
TEST(MarkerRigAccuracy, EitherSideOfTheSameSizeGivesTheSizeWithoutASign) {
  RigTally t;
  RunRig("medium", 126, 4, &t);
  EXPECT_EQ(t.ok, 4) << t.log;
  EXPECT_GE(t.unsigned_rows, 1) << t.log;
  EXPECT_LE(t.yaw_max, 1) << t.log;
  EXPECT_EQ(t.signed_off, 0) << t.log;
}

// One lower marker that could be either, where the right side turns the upper marker 60-70
// degrees round (medium 129 view 3, hard 230 view 3: yaw -55 and 57): past the turn at which
// the bend is measured, but not past the one at which a marker shows. Where the nearer look
// leaves both sides, the upper marker is looked for that far to tell the side (the views were
// lost as "it could be either"); their bend is not measured, and their sign stays unknown (the
// other side found a dark spot).
TEST(MarkerRigAccuracy, AnUpperMarkerTurnedPastTheBendsLimitStillTellsTheSide) {
  RigTally t;
  RunRig("medium", 129, 4, &t);
  RunRig("hard", 230, 4, &t);
  EXPECT_EQ(t.ok, 8) << t.log;
  EXPECT_LE(t.unsigned_rows, 4) << t.log;  // 230 views 0 and 1 likewise
  EXPECT_LE(t.yaw_max, 1.5) << t.log;
  EXPECT_LE(t.bend_mae(), 1.0) << t.log;
  EXPECT_EQ(t.signed_off, 0) << t.log;
}

// One lower marker read as the right one (medium 124, views 1 and 3: yaw -32 and -31), whose
// upper marker is found plainly while the left one's side finds no dark spot where it would put
// it: the upper part tells the sign. (The second side's own spots had stood in for the first
// side's, and the sign was left unknown.)
TEST(MarkerRigAccuracy, TheSecondSideChosenTellsItsSignFromTheFirstSidesSpots) {
  RigTally t;
  RunRig("medium", 124, 4, &t);
  EXPECT_EQ(t.ok, 4) << t.log;
  EXPECT_EQ(t.unsigned_rows, 0) << t.log;
  EXPECT_LE(t.yaw_max, 1.5) << t.log;
  EXPECT_EQ(t.signed_off, 0) << t.log;
}

// A reference whose dark limb meets the joint's own shadow on the wall (easy 18: the lower
// markers 11 px above the image's bottom edge): the steepest step on that side is the shadow's
// far edge, 24 px out, and with the half-width it gives no band of rows was left beside the
// markers, so the reference was refused. Retried at the end of the surface's shading ramp onto
// the flat shadow, it calibrates; such a silhouette sizes no single lower marker (its
// single-marker yaws had come out 6 degrees off), so the views read from both markers are
// answered and the others lost.
TEST(MarkerRigAccuracy, ALimbBesideItsOwnShadowIsFoundWhereTheShadingEnds) {
  RigTally t;
  RunRig("easy", 18, 4, &t);
  EXPECT_EQ(t.ok, 2) << t.log;
  EXPECT_LE(t.yaw_max, 1) << t.log;
  EXPECT_LE(t.bend_mae(), 1.5) << t.log;
  EXPECT_EQ(t.signed_off, 0) << t.log;
}

// A reference seen 14 degrees from aside under side light (medium 115): the limb away from the
// light is a flat self-shadowed band, and the first step met going out was the shading ramp's
// end, too faint to track, 6 px inside the limb. The markers' angles came out 3.6 degrees wide
// and every yaw 10-15 % too large (two views more than 5 degrees off). The trackable step beyond
// the band is the silhouette.
TEST(MarkerRigAccuracy, ALimbsSelfShadowedBandIsPartOfTheJoint) {
  ExpectEveryViewWithin("medium", 115, 1);
}

// A cluttered wall (hard 217): with the faint steps passed over, a triple of two markers and a
// wall blob found a silhouette and calibrated with a marker angle of 11 degrees (42 drawn), its
// lower pair's middle 34 degrees from the upper marker. Refused for that, the search goes on to
// the real triple (45 degrees: its yaws stay within 4 degrees, every sign right).
TEST(MarkerRigAccuracy, ATripleWhoseLowerPairDoesNotFlankTheUpperMarkerIsPassedOver) {
  ExpectEveryViewWithin("hard", 217, 4);
}

// Limbs blurred by the lens: the silhouette's edge fitted without the blur had been placed 2-3 px
// inside a limb, where the blurred start of its shading is as steep as a step, and α came out
// 4.95 (validation medium 153) and 6.5 (validation hard 231) degrees large, single-marker yaws
// up to 5.1 degrees off. With the blur fitted α is within 0.2 and 1.2 degrees.
TEST(MarkerRigAccuracy, ABlurredLimbIsPlacedAtTheLimbNotInsideIt) {
  ExpectEveryViewWithin("medium", 153, 0.5);
  ExpectEveryViewWithin("hard", 231, 1.5);
}

// One lower marker that could be either, and both sides find a dark spot for the upper marker
// with the upper part's silhouette round it (validation easy 38 view 1, easy 49 view 2, hard 257
// view 3; tuning hard 209 view 3): the wrong side's spot is clutter or a paler patch, or the
// same marker with a silhouette half as plain. The test that picks among one side's spots
// (silhouette as plain and spot as dark as the reference's) now picks among the sides, clearly
// or not at all; the views were lost as "it could be either". The sign rests on which spot
// looked more like the marker, so it stays nan.
TEST(MarkerRigAccuracy, TheSideWhoseUpperMarkerLooksClearlyMoreLikeTheReferencesWins) {
  RigTally t;
  RunRig("easy", 38, 4, &t);
  RunRig("easy", 49, 4, &t);
  RunRig("hard", 257, 4, &t);
  RunRig("hard", 209, 4, &t);
  EXPECT_EQ(t.ok, 16) << t.log;
  EXPECT_GE(t.unsigned_rows, 4) << t.log;
  EXPECT_LE(t.yaw_max, 1.5) << t.log;
  EXPECT_LE(t.bend_mae(), 1.0) << t.log;
  EXPECT_EQ(t.signed_off, 0) << t.log;
}

// An upper part bent away from the light (validation hard 259 view 1, hard 238 view 1): the
// stretch from the pivot to the upper marker is shaded at 0.38-0.45 of the reference's level,
// and a spot below half of it had been refused as not on the upper part, so neither side found
// the marker. The lower part's darkest shading in the reference (its limb away from the light)
// bounds how dark the upper part may be.
TEST(MarkerRigAccuracy, AnUpperPartTurnedFromTheLightStillShowsItsMarker) {
  RigTally t;
  RunRig("hard", 259, 4, &t);
  RunRig("hard", 238, 4, &t);
  EXPECT_GE(t.ok, 7) << t.log;
  EXPECT_LE(t.yaw_max, 1.5) << t.log;
  EXPECT_LE(t.bend_mae(), 1.5) << t.log;
  EXPECT_EQ(t.signed_off, 0) << t.log;
}

TEST(MarkerRigAccuracy, HardRigs) {
  RigTally t;
  for (uint64_t seed : {601, 602, 603}) RunRig("hard", seed, 5, &t);
  EXPECT_GE(t.ok, t.views - 4) << t.log;
  EXPECT_LE(t.yaw_mae(), 1.5) << t.log;
  EXPECT_LE(t.bend_mae(), 1.0) << t.log;
  EXPECT_EQ(t.signed_off, 0) << t.log;
}

}  // namespace
}  // namespace armmimic
