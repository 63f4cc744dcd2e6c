#pragma once
// The 3-D view: the mesh shaded with two lights, orbit (left drag), pan
// (right or middle drag) and zoom (wheel). It draws what it is given and
// forwards nothing else.

#include <vector>

#include <QOpenGLBuffer>
#include <QOpenGLFunctions_3_3_Core>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <QOpenGLWidget>
#include <QPoint>
#include <glm/glm.hpp>

#include "core/mesh/mesh.h"

namespace snaxels::ui {

class MeshView : public QOpenGLWidget, protected QOpenGLFunctions_3_3_Core {
    Q_OBJECT
  public:
    explicit MeshView(QWidget* parent = nullptr);
    ~MeshView() override;

    /// Copies the mesh's triangles for drawing and frames the camera on it.
    void setMesh(const Mesh& mesh);
    void clearMesh();
    /// Frames the whole mesh in a three-quarter view.
    void resetCamera();

    QSize sizeHint() const override { return {900, 700}; }

  protected:
    void initializeGL() override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

  private:
    void upload();
    glm::dmat4 viewMatrix() const;
    glm::dmat4 projectionMatrix() const;

    std::vector<float> vertices_; // interleaved position, normal per face corner
    bool dirty_ = false;
    int vertexCount_ = 0;

    glm::dvec3 centre_{0.0};
    double radius_ = 1.0;
    double yaw_ = 0.0, pitch_ = 0.0, distance_ = 3.0;
    glm::dvec3 pan_{0.0};
    QPoint lastPos_;

    QOpenGLShaderProgram program_;
    QOpenGLVertexArrayObject vao_;
    QOpenGLBuffer vbo_{QOpenGLBuffer::VertexBuffer};
    bool glReady_ = false;
};

} // namespace snaxels::ui
