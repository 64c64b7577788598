// The 3-D robot view: the pose it is given with the out-of-limit joints red, the plan's wrist
// path, orbit, zoom and reset, and the Robot panel driving it from the video's frame. Where the
// display offers no OpenGL (the offscreen platform) the view says so and the compact 2-D views
// take over; under a virtual X server (ctest's gui_tests_3d) the arm itself is drawn and checked.
#include <QApplication>
#include <QDockWidget>
#include <QLabel>
#include <QOpenGLWidget>
#include <QPushButton>
#include <QStackedWidget>
#include <QTest>

#include "arm_view_3d.h"
#include "gui_fixture.h"
#include "log_view.h"
#include "main_window.h"
#include "robot_panel.h"
#include "robot_plan.h"
#include "robot_preview.h"
#include "video_player.h"
#include "video_view.h"

#include "armmimic/core/angle_file.h"
#include "test_util.h"

namespace armmimic::test {
namespace {

using gui::ArmView3D;

// Pixels of the view that are the red of an out-of-limit part.
int RedPixels(const QImage& image) {
  int n = 0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const QColor c = image.pixelColor(x, y);
      n += c.red() > 150 && c.green() < 90 && c.blue() < 90 ? 1 : 0;
    }
  }
  return n;
}

class ArmView3DTest : public GuiTest {};

TEST_F(ArmView3DTest, ShowsThePoseWithOutOfLimitJointsRed) {
  ArmView3D view;
  view.resize(480, 360);
  view.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&view));
  view.setPose({0, -90, -30, 0, 0, 0}, "inside");
  EXPECT_TRUE(view.violatingJoints().isEmpty());
  EXPECT_EQ(view.valuesText(), "J1 0.0  J2 -90.0  J3 -30.0  J4 0.0  J5 0.0  J6 0.0");
  auto* values = view.findChild<QLabel*>("armView3dValues");
  EXPECT_FALSE(values->text().contains("d03b2f"));
  view.setPose({0, -90, 60, 0, 0, 0}, "J3 past 45");
  EXPECT_EQ(view.violatingJoints(), QList<int>{2});
  EXPECT_TRUE(values->text().contains("d03b2f"));  // J3's value in red
  EXPECT_EQ(view.findChild<QLabel*>("armView3dCaption")->text(), "J3 past 45");
  // The run under a virtual X server promises OpenGL: it must draw, not fall back.
  if (qEnvironmentVariableIsSet("ARMMIMIC_EXPECT_OPENGL")) {
    ASSERT_TRUE(ArmView3D::OpenGlAvailable());
  }
  if (!ArmView3D::OpenGlAvailable()) {
    EXPECT_FALSE(view.drawsIn3D());
    auto* note = view.findChild<QLabel*>("armView3dFallback");
    ASSERT_NE(note, nullptr);
    EXPECT_TRUE(note->isVisible());
    EXPECT_TRUE(note->text().contains("OpenGL"));
    return;
  }
  // Drawn: the forearm and elbow red, and only while J3 is outside its limits.
  auto* gl = view.findChild<QOpenGLWidget*>();
  ASSERT_NE(gl, nullptr);
  QTest::qWait(50);
  const int red_outside = RedPixels(gl->grabFramebuffer());
  view.setPose({0, -90, -30, 0, 0, 0}, "inside");
  QTest::qWait(50);
  const QImage inside = gl->grabFramebuffer();
  EXPECT_GT(red_outside, 200);
  EXPECT_EQ(RedPixels(inside), 0);
  // The arm is there (blue), not an empty picture.
  int blue = 0;
  for (int y = 0; y < inside.height(); y += 2) {
    for (int x = 0; x < inside.width(); x += 2) {
      const QColor c = inside.pixelColor(x, y);
      blue += c.blue() > 150 && c.red() < 120 ? 1 : 0;
    }
  }
  EXPECT_GT(blue, 100);
}

TEST_F(ArmView3DTest, AFileWithThreeDColumnsShowsThePersonsArmBesideTheRobot) {
  // A pose-engine file of the person's left arm (image right) with the 3-D columns: level and
  // reaching 60 degrees towards the camera.
  TempDir dir;
  const std::string path = dir.file("arm3d.tsv");
  AngleFileWriter writer;
  ASSERT_TRUE(writer
                  .Open(path, {{"engine", "pose"}, {"fps", "30"}, {"pose.side", "left"}}, false,
                        true, false, true)
                  .ok());
  for (int f = 0; f < 10; ++f) {
    AngleRow r;
    r.frame = f;
    r.time_s = f / 30.0;
    r.status = RowStatus::kOk;
    r.upper_deg = 0;
    r.fore_deg = 0;
    r.bend_deg = 0;
    r.upper_az_deg = r.fore_az_deg = 60;
    r.upper_el_deg = r.fore_el_deg = 0;
    r.elbow_deg = 180;
    r.confidence = 0.9;
    ASSERT_TRUE(writer.Write(r).ok());
  }
  ASSERT_TRUE(writer.Commit().ok());
  gui::RobotPlan plan;
  ASSERT_TRUE(plan.Load(path).ok());
  robot::PlannerOptions options;
  // The preview turns J1 by the azimuth, as the plan does.
  robot::JointArray j;
  ASSERT_TRUE(plan.MappedPose(5, options, &j));
  EXPECT_NEAR(j[0], 60, 1e-9);
  EXPECT_NEAR(j[1], -90, 1e-9);
  robot::PersonArm arm;
  ASSERT_TRUE(plan.PersonArmAt(5, options, &arm));
  EXPECT_NEAR((arm.elbow - arm.shoulder).normalized().y(), std::sin(60 * M_PI / 180), 1e-9);
  // From the 2-D columns there is no waist turn and no person's arm.
  options.mapping.arm_3d = false;
  ASSERT_TRUE(plan.MappedPose(5, options, &j));
  EXPECT_NEAR(j[0], 0, 1e-9);
  EXPECT_FALSE(plan.PersonArmAt(5, options, &arm));
  // The view draws it and says so under the arm.
  ArmView3D view;
  view.setPose({60, -90, 0, 0, 0, 0}, "frame 5");
  view.setPersonArm(arm);
  ASSERT_TRUE(view.personArm().has_value());
  EXPECT_TRUE(view.findChild<QLabel*>("armView3dCaption")->text().contains("the person's arm"));
  view.setPersonArm(std::nullopt);
  EXPECT_EQ(view.findChild<QLabel*>("armView3dCaption")->text(), "frame 5");
}

TEST_F(ArmView3DTest, OrbitZoomAndResetMoveTheCamera) {
  ArmView3D view;
  view.resize(400, 300);
  view.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&view));
  const gui::ArmCamera start = view.camera();
  const QVector3D eye = start.eye();
  view.orbit(30, 10);
  EXPECT_DOUBLE_EQ(view.camera().yaw_deg, start.yaw_deg + 30);
  EXPECT_DOUBLE_EQ(view.camera().pitch_deg, start.pitch_deg + 10);
  // The eye keeps its distance to the target while it orbits.
  EXPECT_NEAR((view.camera().eye() - view.camera().target).length(), start.distance_m, 1e-4);
  view.orbit(0, 500);
  EXPECT_DOUBLE_EQ(view.camera().pitch_deg, 89);  // never over the top
  view.zoom(2);
  EXPECT_DOUBLE_EQ(view.camera().distance_m, start.distance_m / 2);
  view.zoom(1000);
  EXPECT_DOUBLE_EQ(view.camera().distance_m, 1.5);
  view.resetView();
  EXPECT_EQ(view.camera().eye(), eye);
  if (!view.drawsIn3D()) return;
  // With the mouse: a drag orbits, the wheel zooms, a double-click resets.
  auto* gl = view.findChild<QOpenGLWidget*>();
  QTest::mousePress(gl, Qt::LeftButton, Qt::NoModifier, QPoint(100, 100));
  QTest::mouseMove(gl, QPoint(150, 120));
  QTest::mouseRelease(gl, Qt::LeftButton, Qt::NoModifier, QPoint(150, 120));
  EXPECT_NE(view.camera().yaw_deg, start.yaw_deg);
  QTest::mouseDClick(gl, Qt::LeftButton, Qt::NoModifier, QPoint(150, 120));
  EXPECT_EQ(view.camera().eye(), eye);
}

TEST_F(ArmView3DTest, TheRobotPanelDrivesItFromTheVideoAndThePlan) {
  gui::MainWindow w;
  ShowAndAnalyze(w);
  gui::RobotPanel* panel = w.robotPanel();
  w.findChild<QDockWidget*>("robotDock")->raise();
  ArmView3D* view = panel->view3d();
  ASSERT_TRUE(panel->plan().planned()) << w.log()->text().toStdString();
  EXPECT_EQ(view->path().size(), panel->plan().trajectory().keyframes.size());
  // The pose follows the video's frame, the same in 3-D and in the compact views.
  w.player()->seek(60);
  ASSERT_TRUE(WaitUntil([&] { return w.view()->frameIndex() == 60; }));
  robot::JointArray mapped;
  ASSERT_TRUE(panel->plan().MappedPose(60, panel->plannerOptions(), &mapped));
  EXPECT_EQ(view->pose(), mapped);
  EXPECT_EQ(panel->preview()->pose(), mapped);
  EXPECT_TRUE(view->caption().contains("frame 60"));
  // Animated, it moves along the plan.
  auto* animate = panel->findChild<QPushButton*>("animateButton");
  animate->setChecked(true);
  const robot::JointArray before = view->pose();
  ASSERT_TRUE(WaitUntil([&] { return view->pose() != before; }, 5000));
  EXPECT_TRUE(view->caption().startsWith("plan t="));
  animate->setChecked(false);
  // The compact 2-D views stay available, and are shown where OpenGL is not.
  auto* compact = panel->findChild<QPushButton*>("compactButton");
  auto* stack = panel->findChild<QStackedWidget*>("previewStack");
  EXPECT_EQ(compact->isChecked(), !view->drawsIn3D());
  compact->setChecked(false);
  EXPECT_EQ(stack->currentWidget()->findChild<ArmView3D*>(), view);
  compact->setChecked(true);
  EXPECT_EQ(stack->currentWidget()->findChild<gui::RobotPreview*>(), panel->preview());
  EXPECT_FALSE(panel->findChild<QPushButton*>("resetViewButton")->isEnabled());
}

}  // namespace
}  // namespace armmimic::test
