#include "arm_view_3d.h"

#include <algorithm>
#include <cmath>

#include <QLabel>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QVBoxLayout>

#include "arm_gl_view.h"

namespace armmimic::gui {
namespace {

constexpr float kRadPerDeg = 3.14159265f / 180.0f;

}  // namespace

void ArmCamera::orbit(double dyaw_deg, double dpitch_deg) {
  yaw_deg = std::remainder(yaw_deg + dyaw_deg, 360.0);
  pitch_deg = std::clamp(pitch_deg + dpitch_deg, -10.0, 89.0);
}

void ArmCamera::zoom(double factor) {
  if (factor > 0 && std::isfinite(factor)) distance_m = std::clamp(distance_m / factor, 1.5, 12.0);
}

QVector3D ArmCamera::eye() const {
  const float yaw = float(yaw_deg) * kRadPerDeg;
  const float pitch = float(pitch_deg) * kRadPerDeg;
  const float d = float(distance_m);
  return target + d * QVector3D(std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw),
                                std::sin(pitch));
}

QMatrix4x4 ArmCamera::view() const {
  QMatrix4x4 m;
  m.lookAt(eye(), target, QVector3D(0, 0, 1));
  return m;
}

bool ArmView3D::OpenGlAvailable() {
  static const bool available = [] {
    QOpenGLContext context;
    if (!context.create()) return false;
    QOffscreenSurface surface;
    surface.setFormat(context.format());
    surface.create();
    return surface.isValid() && context.makeCurrent(&surface);
  }();
  return available;
}

ArmView3D::ArmView3D(QWidget* parent)
    : QWidget(parent), caption_label_(new QLabel), values_label_(new QLabel) {
  setObjectName("armView3d");
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(0);
  caption_label_->setObjectName("armView3dCaption");
  caption_label_->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
  caption_label_->setForegroundRole(QPalette::PlaceholderText);
  values_label_->setObjectName("armView3dValues");
  values_label_->setTextFormat(Qt::RichText);
  layout->addWidget(caption_label_);
  if (OpenGlAvailable()) {
    gl_ = new ArmGlView(this);
    layout->addWidget(gl_);
  } else {
    fallback_ =
        new QLabel(tr("The 3-D view needs OpenGL, which this display does not offer. "
                      "The compact 2-D views show the same pose."));
    fallback_->setObjectName("armView3dFallback");
    fallback_->setWordWrap(true);
    fallback_->setAlignment(Qt::AlignCenter);
    layout->addWidget(fallback_);
  }
  layout->addWidget(values_label_);
  layout->setStretch(1, 1);
  showTexts();
}

void ArmView3D::setLimits(const robot::JointLimits& limits) {
  limits_ = limits;
  redraw();
}

void ArmView3D::setPose(const robot::JointArray& joint_deg, const QString& caption) {
  pose_ = joint_deg;
  caption_ = caption;
  redraw();
}

void ArmView3D::setPath(const robot::Trajectory& trajectory) {
  path_.clear();
  path_.reserve(trajectory.keyframes.size());
  for (const robot::Keyframe& k : trajectory.keyframes) {
    path_.push_back(robot::ForwardKinematics(k.joint_deg).wrist);
  }
  redraw();
}

void ArmView3D::setPersonArm(const std::optional<robot::PersonArm>& arm) {
  person_ = arm;
  redraw();
}

QList<int> ArmView3D::violatingJoints() const {
  QList<int> out;
  const std::array<bool, robot::kJoints> outside = robot::JointsOutside(limits_, pose_);
  for (int j = 0; j < robot::kJoints; ++j) {
    if (outside[j]) out << j;
  }
  return out;
}

void ArmView3D::orbit(double dyaw_deg, double dpitch_deg) {
  camera_.orbit(dyaw_deg, dpitch_deg);
  redraw();
  emit viewChanged();
}

void ArmView3D::zoom(double factor) {
  camera_.zoom(factor);
  redraw();
  emit viewChanged();
}

void ArmView3D::resetView() {
  camera_.reset();
  redraw();
  emit viewChanged();
}

void ArmView3D::redraw() {
  showTexts();
  if (gl_) gl_->update();
}

QString ArmView3D::valuesText() const {
  QStringList parts;
  for (int j = 0; j < robot::kJoints; ++j) {
    parts << QString("J%1 %2").arg(j + 1).arg(pose_[j], 0, 'f', 1);
  }
  return parts.join("  ");
}

void ArmView3D::showTexts() {
  const QList<int> bad = violatingJoints();
  QStringList parts;
  for (int j = 0; j < robot::kJoints; ++j) {
    const QString t = QString("J%1&nbsp;%2").arg(j + 1).arg(pose_[j], 0, 'f', 1);
    parts << (bad.contains(j) ? QString("<span style='color:#d03b2f'><b>%1</b></span>").arg(t) : t);
  }
  values_label_->setText(parts.join("&nbsp;&nbsp; "));
  caption_label_->setText(
      person_ ? tr("%1; the person's arm in 3-D beside it, in green").arg(caption_) : caption_);
}

}  // namespace armmimic::gui
