#include "arm_gl_view.h"

#include <cmath>

#include <QMouseEvent>
#include <QQuaternion>
#include <QWheelEvent>

#include "arm_view_3d.h"

namespace armmimic::gui {
namespace {

const QColor kArm(0x2a, 0x82, 0xda);
const QColor kBase(0x8a, 0x90, 0x98);
const QColor kBad(0xd0, 0x3b, 0x2f);
const QColor kPath(0xe0, 0xa0, 0x00);
const QColor kPerson(0x3c, 0xa0, 0x5a);

const char* kVertexShader = R"(
attribute vec3 position;
attribute vec3 normal;
uniform mat4 mvp;
uniform mat3 normal_matrix;
varying vec3 n;
void main() {
  n = normal_matrix * normal;
  gl_Position = mvp * vec4(position, 1.0);
})";

const char* kFragmentShader = R"(
#ifdef GL_ES
precision mediump float;
#endif
varying vec3 n;
uniform vec4 color;
uniform float lit;
void main() {
  // A head light a little above and to the left of the eye.
  float d = 0.35 + 0.65 * max(dot(normalize(n), normalize(vec3(-0.3, 0.5, 1.0))), 0.0);
  gl_FragColor = vec4(color.rgb * mix(1.0, d, lit), color.a);
})";

void Push(QVector<float>* v, const QVector3D& p, const QVector3D& n) {
  *v << p.x() << p.y() << p.z() << n.x() << n.y() << n.z();
}

// A cylinder of radius 1 from z = 0 to z = 1 with both ends closed, as triangles.
QVector<float> CylinderMesh(int sides) {
  QVector<float> v;
  const float step = 2 * 3.14159265f / sides;
  for (int i = 0; i < sides; ++i) {
    const QVector3D a(std::cos(i * step), std::sin(i * step), 0);
    const QVector3D b(std::cos((i + 1) * step), std::sin((i + 1) * step), 0);
    const QVector3D up(0, 0, 1);
    Push(&v, a, a), Push(&v, b, b), Push(&v, b + up, b);
    Push(&v, a, a), Push(&v, b + up, b), Push(&v, a + up, a);
    Push(&v, QVector3D(), -up), Push(&v, b, -up), Push(&v, a, -up);
    Push(&v, up, up), Push(&v, a + up, up), Push(&v, b + up, up);
  }
  return v;
}

// A sphere of radius 1, as triangles.
QVector<float> SphereMesh(int rings, int sides) {
  QVector<float> v;
  auto at = [&](int r, int s) {
    const float theta = 3.14159265f * r / rings;
    const float phi = 2 * 3.14159265f * s / sides;
    return QVector3D(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                     std::cos(theta));
  };
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < sides; ++s) {
      const QVector3D a = at(r, s), b = at(r + 1, s), c = at(r + 1, s + 1), d = at(r, s + 1);
      Push(&v, a, a), Push(&v, b, b), Push(&v, c, c);
      Push(&v, a, a), Push(&v, c, c), Push(&v, d, d);
    }
  }
  return v;
}

// Floor lines every 0.25 m over 3 x 3 m around the base.
QVector<float> GridMesh() {
  QVector<float> v;
  const QVector3D up(0, 0, 1);
  for (int i = -6; i <= 6; ++i) {
    const float c = i * 0.25f;
    Push(&v, QVector3D(c, -1.5f, 0), up), Push(&v, QVector3D(c, 1.5f, 0), up);
    Push(&v, QVector3D(-1.5f, c, 0), up), Push(&v, QVector3D(1.5f, c, 0), up);
  }
  return v;
}

QVector3D V(const Eigen::Vector3d& p) {
  return QVector3D(float(p.x()), float(p.y()), float(p.z()));
}

}  // namespace

ArmGlView::ArmGlView(ArmView3D* owner) : QOpenGLWidget(owner), owner_(owner) {
  setObjectName("armGlView");
  QSurfaceFormat f = format();
  f.setDepthBufferSize(24);
  f.setSamples(4);
  setFormat(f);
  setToolTip(tr("Drag to orbit, wheel to zoom, double-click to reset the view"));
}

ArmGlView::~ArmGlView() { releaseGl(); }

void ArmGlView::releaseGl() {
  if (!context() || !program_) return;
  makeCurrent();
  for (Mesh* m : {&cylinder_, &sphere_, &grid_, &path_}) {
    m->buffer.destroy();
    m->vertices = 0;
  }
  program_.reset();
  doneCurrent();
}

void ArmGlView::upload(Mesh* mesh, const QVector<float>& data) {
  if (!mesh->buffer.isCreated()) mesh->buffer.create();
  mesh->buffer.bind();
  mesh->buffer.allocate(data.constData(), int(data.size() * sizeof(float)));
  mesh->buffer.release();
  mesh->vertices = int(data.size() / 6);
}

void ArmGlView::initializeGL() {
  initializeOpenGLFunctions();
  // Moving the panel to a window of its own makes a new context: build everything again then.
  connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &ArmGlView::releaseGl,
          Qt::UniqueConnection);
  program_ = std::make_unique<QOpenGLShaderProgram>();
  program_->addShaderFromSourceCode(QOpenGLShader::Vertex, kVertexShader);
  program_->addShaderFromSourceCode(QOpenGLShader::Fragment, kFragmentShader);
  program_->bindAttributeLocation("position", 0);
  program_->bindAttributeLocation("normal", 1);
  program_->link();
  upload(&cylinder_, CylinderMesh(28));
  upload(&sphere_, SphereMesh(10, 20));
  upload(&grid_, GridMesh());
}

void ArmGlView::draw(Mesh& mesh, GLenum mode, const QMatrix4x4& model, const QColor& color,
                     bool lit) {
  if (mesh.vertices == 0) return;
  program_->setUniformValue("mvp", projection_view_ * model);
  program_->setUniformValue("normal_matrix", (view_ * model).normalMatrix());
  program_->setUniformValue("color", color);
  program_->setUniformValue("lit", lit ? 1.0f : 0.0f);
  mesh.buffer.bind();
  program_->enableAttributeArray(0);
  program_->enableAttributeArray(1);
  program_->setAttributeBuffer(0, GL_FLOAT, 0, 3, 6 * sizeof(float));
  program_->setAttributeBuffer(1, GL_FLOAT, 3 * sizeof(float), 3, 6 * sizeof(float));
  glDrawArrays(mode, 0, mesh.vertices);
  mesh.buffer.release();
}

void ArmGlView::drawRod(const QVector3D& from, const QVector3D& to, float radius,
                        const QColor& color) {
  const QVector3D axis = to - from;
  QMatrix4x4 model;
  model.translate(from);
  model.rotate(QQuaternion::rotationTo(QVector3D(0, 0, 1), axis.normalized()));
  model.scale(radius, radius, axis.length());
  draw(cylinder_, GL_TRIANGLES, model, color, true);
}

void ArmGlView::drawBall(const QVector3D& centre, float radius, const QColor& color) {
  QMatrix4x4 model;
  model.translate(centre);
  model.scale(radius);
  draw(sphere_, GL_TRIANGLES, model, color, true);
}

void ArmGlView::paintGL() {
  if (!program_) return;
  const QColor background = palette().color(QPalette::Base);
  glClearColor(background.redF(), background.greenF(), background.blueF(), 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  QMatrix4x4 projection;
  projection.perspective(35.0f, float(width()) / float(std::max(1, height())), 0.1f, 50.0f);
  view_ = owner_->camera().view();
  projection_view_ = projection * view_;
  program_->bind();
  draw(grid_, GL_LINES, QMatrix4x4(), palette().color(QPalette::Mid), false);

  const robot::ArmPose pose = robot::ForwardKinematics(owner_->pose());
  const std::array<bool, robot::kJoints> bad =
      robot::JointsOutside(owner_->limits(), owner_->pose());
  for (const robot::ArmPart& part : robot::ArmParts(pose)) {
    const float r = float(part.radius_m);
    const QColor color = part.joint < 0 ? kBase : bad[part.joint] ? kBad : kArm;
    drawRod(V(part.from), V(part.to), r, color);
    // Rounded joints at both ends of the links.
    if (part.joint >= 1 && part.joint <= 2) {
      for (const QVector3D& end : {V(part.from), V(part.to)}) drawBall(end, r, color);
    }
  }
  if (const std::optional<robot::PersonArm>& arm = owner_->personArm()) {
    // The person's arm beside the robot: two rods with round joints, the robot's lengths.
    const std::array<QVector3D, 3> points = {V(arm->shoulder), V(arm->elbow), V(arm->wrist)};
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
      drawRod(points[i], points[i + 1], 0.035f, kPerson);
    }
    for (const QVector3D& p : points) drawBall(p, 0.05f, kPerson);
  }
  const std::vector<Eigen::Vector3d>& path = owner_->path();
  if (path.size() > 1) {
    QVector<float> line;
    for (const Eigen::Vector3d& p : path) Push(&line, V(p), QVector3D(0, 0, 1));
    upload(&path_, line);
    draw(path_, GL_LINE_STRIP, QMatrix4x4(), kPath, false);
  }
  program_->release();
  glDisable(GL_DEPTH_TEST);
}

void ArmGlView::mousePressEvent(QMouseEvent* event) { last_pos_ = event->position().toPoint(); }

void ArmGlView::mouseMoveEvent(QMouseEvent* event) {
  if (!(event->buttons() & Qt::LeftButton)) return;
  const QPoint pos = event->position().toPoint();
  const QPoint d = pos - last_pos_;
  last_pos_ = pos;
  owner_->orbit(-0.4 * d.x(), 0.4 * d.y());
}

void ArmGlView::mouseDoubleClickEvent(QMouseEvent*) { owner_->resetView(); }

void ArmGlView::wheelEvent(QWheelEvent* event) {
  owner_->zoom(std::pow(1.0015, event->angleDelta().y()));
  event->accept();
}

}  // namespace armmimic::gui
