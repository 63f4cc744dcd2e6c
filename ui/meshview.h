#pragma once
// The 3-D view: the mesh shaded by the document's light (with a soft fill from the viewer) and the contours drawn on
// it (per-kind colours, hidden parts dashed), orbit (left drag), pan (right
// or middle drag), zoom (wheel) and the light turned by Shift+left drag. It draws what it is given and reports
// camera changes; it computes nothing itself.

#include <optional>
#include <vector>

#include <QOpenGLBuffer>
#include <QOpenGLFunctions_3_3_Core>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <QOpenGLWidget>
#include <QPoint>
#include <QRectF>
#include <glm/glm.hpp>

#include "snaxels/mesh/mesh.h"
#include "snaxels/mesh/topology.h"
#include "snaxels/scene/camera.h"
#include "snaxels/scene/orbit.h"
#include "snaxels/style/style.h"

namespace snaxels::ui {

/// Triangles ready for the GPU (position and normal per corner), and the
/// bounding sphere the camera frames; built off the GUI thread for big meshes.
struct MeshGeometry {
    std::vector<float> vertices;
    glm::dvec3 centre{0.0};
    double radius = 1.0;
};

/// The triangles to draw; above @p max_faces (0: no limit) a lighter mesh
/// made by vertex clustering, for software renderers.
MeshGeometry mesh_geometry(const MeshTopology& mesh, std::size_t max_faces = 0);

/// The face budget of the view's renderer (0: none; set for software renderers).
std::size_t display_face_budget();

/// A contour polyline to draw on the surface.
struct ContourStrip {
    std::vector<glm::vec3> points;
    glm::vec3 colour{0.0f};
    bool hidden = false;
    bool closed = false;
};

/// How the 3-D view colours the surface by planar-map region: the class of
/// each point from the light (N.L for shadow and isophote bands, R.V for
/// highlights), as the fills of the exported SVG classify it.
struct RegionShading {
    bool enabled = false;
    Light light;
    bool shadow_contour = true; ///< the map has a shadow contour (else every unlit point is lit)
    glm::vec3 shadow{0.36f, 0.42f, 0.58f};
    glm::vec3 lit{0.93f, 0.86f, 0.72f};
    std::vector<std::pair<double, glm::vec3>> bands;      ///< (k, colour), ascending k: N.L >= k
    std::vector<std::pair<double, glm::vec3>> highlights; ///< (k, colour), ascending k: R.V >= k
};

class LightGlobe;

class MeshView : public QOpenGLWidget, protected QOpenGLFunctions_3_3_Core {
    Q_OBJECT
  public:
    explicit MeshView(QWidget* parent = nullptr);
    ~MeshView() override;

    /// Copies the mesh's triangles for drawing, the orbit about its centre
    /// (the camera stays until setOrbit or resetCamera frames it).
    void setMesh(const Mesh& mesh);
    /// The same with triangles prepared by mesh_geometry (on any thread).
    void setGeometry(MeshGeometry geometry);
    /// Replaces the triangles of the same mesh in another pose (a clip
    /// frame) without moving the camera.
    void setPose(MeshGeometry geometry);
    void clearMesh();
    /// Frames the whole mesh, its front seen from a little above and to the
    /// side (View > Reset Camera): an edit (viewEdited).
    void resetCamera();
    /// Frames the parts selected in the Objects panel (the tinted
    /// triangles) as resetCamera frames the whole: View > Frame Selected.
    /// With none selected, frames the whole.
    void frameSelected();
    /// The orbit resetCamera moves to: the pose drawn, framed.
    OrbitView poseFraming() const;
    /// Looks through @p camera (one of the file's cameras, posed for the
    /// frame) instead of the orbit; nullopt goes back to the orbit. Orbit,
    /// pan and zoom then leave the view as it is and say why
    /// (lockedToFileCamera).
    void setFileCamera(const std::optional<Camera>& camera);
    bool looksThroughFileCamera() const { return fileCamera_.has_value(); }
    /// Turns the mesh about the vertical axis through its centre, as a
    /// turntable at @p degrees (the user's orbit is kept on top of it).
    void setTurntable(double degrees);
    /// Frames the mesh's centre (no pan), as turntables and exports assume.
    void centreView();
    /// Colours the surface by region (or not, when not enabled).
    void setRegionShading(RegionShading shading);
    const RegionShading& regionShading() const { return shading_; }
    /// The point the camera orbits (the mesh's centre, as framed).
    glm::dvec3 orbitCentre() const { return centre_; }
    /// Replaces the contours drawn over the mesh.
    /// The contours to draw, computed for the camera @p seenFrom.
    void setContours(std::vector<ContourStrip> strips, const Camera& seenFrom);
    /// The contours drawn were computed for another camera than the view's
    /// (an orbit under way): they are drawn against the surface's depth.
    bool contoursStale() const;
    /// The view's camera, as the engine sees it (a perspective camera).
    Camera camera() const;
    /// The camera before the turntable turns (frame 0), with world +Y as up:
    /// what an animation export starts from.
    Camera baseCamera() const;
    /// The orbit the camera follows (a project file keeps it).
    const OrbitView& orbit() const { return orbit_; }
    /// Moves the camera to @p orbit (its centre stays the mesh's, the
    /// turntable angle the timeline's).
    void setOrbit(const OrbitView& orbit);
    /// Tints @p triangles (three corners each) over the surface: a part
    /// selected in the Objects panel. Empty: no tint.
    void setHighlight(std::vector<glm::vec3> triangles);
    std::size_t highlightTriangles() const { return highlight_.size() / 3; }
    /// The canvas the drawing is made on (its pixels, margin and page, a
    /// file camera's aspect applied): the view shows the drawing's frame,
    /// the canvas fitted inside it, with what lies outside darkened, and
    /// projects as the drawing does, so the two show the same picture.
    void setCanvas(int width, int height, double margin, const Page& page);
    /// The drawing's frame in the view's pixels.
    QRectF frameRect() const;
    /// Whether the frame's border and darkened surround are drawn (View >
    /// Camera Frame); the view frames the picture as the drawing does either way.
    void setFrameShown(bool shown);
    bool frameShown() const { return frameShown_; }

  signals:
    /// The camera moved (orbit, pan, zoom, reset or a new mesh).
    void cameraChanged();
    /// An orbit, pan or zoom while the view looks through a file's camera.
    void lockedToFileCamera();
    /// The user moved the camera (each step of a drag that moves it, a
    /// wheel turn, a reset): an edit of the document's view (a drag's steps
    /// merge into one undo step there).
    void viewEdited();
    /// Shift+drag turns the light: by @p angle_a about @p axis_a, then by
    /// @p angle_b about @p axis_b (world axes, radians).
    void lightDragged(glm::dvec3 axis_a, double angle_a, glm::dvec3 axis_b, double angle_b);

  public:

    QSize sizeHint() const override { return {900, 700}; }

  protected:
    void initializeGL() override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

  private:
    void upload();
    /// Frames the bounding sphere of @p points (the whole mesh's, without): an edit.
    void frame(const std::vector<glm::vec3>& points);
    /// The orbit that frames @p points, keeping the projection, lens and turntable.
    OrbitView framing(const std::vector<glm::vec3>& points) const;
    /// The corners of the triangles drawn (the pose shown).
    std::vector<glm::vec3> drawnPoints() const;
    void setRegionUniforms();
    void buildSurfaceProgram();
    void drawContours(const glm::mat4& mvp, bool stale);
    void drawHighlight(const glm::mat4& mvp);
    void resizeEvent(QResizeEvent* event) override;
    void uploadContours();
    /// Puts @p data, in the line shader's layout (position, colour, hidden
    /// flag, arc length), into @p vbo with @p vao's attributes.
    void uploadLineVertices(QOpenGLVertexArrayObject& vao, QOpenGLBuffer& vbo, const std::vector<float>& data);
    glm::dmat4 viewMatrix() const;
    glm::dmat4 projectionMatrix() const;
    /// View pixels per canvas pixel: the canvas fitted into the view.
    double frameScale() const;
    /// The drawing's projection of the view's camera onto the canvas.
    ImageProjection drawingProjection() const;
    /// World units a view pixel spans at the orbited point.
    double worldPerPixel() const;
    /// Darkens the view outside the frame and draws its border.
    void drawFrame();

    std::vector<float> vertices_; // interleaved position, normal per face corner
    bool dirty_ = false;
    int vertexCount_ = 0;

    LightGlobe* globe_; ///< where the light is, in the top right corner
    glm::dvec3 centre_{0.0};
    double radius_ = 1.0;
    OrbitView orbit_;
    std::optional<Camera> fileCamera_;
    Style canvas_; ///< the drawing's canvas (its size, margin and page only)
    bool frameShown_ = true;
    QPoint lastPos_;
    /// A press this view had, not released yet: only its drag can be an
    /// edit (a release whose press went elsewhere, a menu's, is none).
    bool pressed_ = false;
    bool dragged_ = false, draggingLight_ = false;

    RegionShading shading_;
    std::vector<ContourStrip> strips_;
    Camera contourCamera_; ///< the camera strips_ were computed for
    std::vector<float> lineVertices_; // position, colour, hidden flag, arc length
    std::vector<std::pair<int, int>> lineRanges_; // first vertex, count per strip
    bool linesDirty_ = false;
    QOpenGLShaderProgram lineProgram_;
    QOpenGLVertexArrayObject lineVao_;
    QOpenGLBuffer lineVbo_{QOpenGLBuffer::VertexBuffer};
    std::vector<glm::vec3> highlight_; ///< triangles tinted over the surface
    bool highlightDirty_ = false;
    int highlightVertices_ = 0;
    QOpenGLVertexArrayObject highlightVao_;
    QOpenGLBuffer highlightVbo_{QOpenGLBuffer::VertexBuffer};
    QOpenGLVertexArrayObject frameVao_; ///< the frame's darkened surround and border
    QOpenGLBuffer frameVbo_{QOpenGLBuffer::VertexBuffer};

    QOpenGLShaderProgram program_;
    int bandCapacity_ = 8, highlightCapacity_ = 4; ///< levels the surface shader's arrays hold
    bool programStale_ = false;                    ///< the shader must grow to hold the levels
    QOpenGLVertexArrayObject vao_;
    QOpenGLBuffer vbo_{QOpenGLBuffer::VertexBuffer};
    bool glReady_ = false;
};

} // namespace snaxels::ui
