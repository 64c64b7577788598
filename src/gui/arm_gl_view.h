// ArmGlView: ArmView3D's OpenGL drawing surface. It draws what its owner holds (pose, limits,
// plan path, camera): a floor grid, the arm's parts as shaded cylinders and the wrist path; mouse
// input goes back to the owner's camera. It draws no text: glyphs cached in a GL context outlive
// it in Qt's font cache and crash when that cache is cleaned, so the owner shows texts in labels.
#pragma once

#include <memory>

#include <QOpenGLBuffer>
#include <QOpenGLFunctions>
#include <QOpenGLShaderProgram>
#include <QOpenGLWidget>
#include <QPoint>

namespace armmimic::gui {

class ArmView3D;

class ArmGlView : public QOpenGLWidget, protected QOpenGLFunctions {
  Q_OBJECT
 public:
  explicit ArmGlView(ArmView3D* owner);
  ~ArmGlView() override;

 protected:
  void initializeGL() override;
  void paintGL() override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;

 private:
  struct Mesh {
    QOpenGLBuffer buffer{QOpenGLBuffer::VertexBuffer};
    int vertices = 0;
  };
  void upload(Mesh* mesh, const QVector<float>& data);
  // Frees what lives in the GL context (it goes when the panel floats or docks again).
  void releaseGl();
  void draw(Mesh& mesh, GLenum mode, const QMatrix4x4& model, const QColor& color, bool lit);
  // A lit cylinder of `radius` from `from` to `to`, and a lit sphere: the arms' solids.
  void drawRod(const QVector3D& from, const QVector3D& to, float radius, const QColor& color);
  void drawBall(const QVector3D& centre, float radius, const QColor& color);

  ArmView3D* owner_;
  std::unique_ptr<QOpenGLShaderProgram> program_;
  Mesh cylinder_;
  Mesh sphere_;
  Mesh grid_;
  Mesh path_;
  QMatrix4x4 projection_view_;
  QMatrix4x4 view_;
  QPoint last_pos_;
};

}  // namespace armmimic::gui
