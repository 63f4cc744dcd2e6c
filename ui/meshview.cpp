#include "ui/meshview.h"

#include <utility>
#include <algorithm>
#include <limits>
#include <atomic>
#include <unordered_map>
#include <cmath>

#include <QMouseEvent>
#include <QPainter>
#include <QVector3D>
#include <QWheelEvent>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "snaxels/planarmap/region.h"

namespace snaxels::ui {

/// Where the light comes from, on a small globe in the view's corner: the
/// dot is filled when the light is on the viewer's side, hollow behind it;
/// the hint says how to turn it. A child widget over the view, so it is
/// painted (and grabbed) like any other.
class LightGlobe final : public QWidget {
  public:
    explicit LightGlobe(MeshView* view) : QWidget(view), view_(view) {
        setAttribute(Qt::WA_TransparentForMouseEvents);
        setAttribute(Qt::WA_NoSystemBackground);
        setObjectName("lightGlobe");
        resize(140, 78);
    }
    void setActive(bool active) {
        active_ = active;
        update();
    }

  protected:
    void paintEvent(QPaintEvent*) override {
        const Light& light = view_->regionShading().light;
        glm::dvec3 dir = light.point ? light.pos - view_->orbitCentre() : light.dir;
        if (!(glm::length(dir) > 0.0)) return;
        dir = glm::normalize(dir);
        glm::dvec3 right, up;
        const Camera cam = view_->camera();
        cam.screen_basis(right, up);
        const double x = glm::dot(dir, right), y = glm::dot(dir, up), z = glm::dot(dir, -cam.forward());
        QPainter painter(this);
        painter.setRenderHint(QPainter::Antialiasing);
        const double r = 22.0;
        const QPointF c(width() - r - 10.0, r + 8.0);
        const int alpha = active_ ? 230 : 130;
        painter.setPen(QPen(QColor(200, 200, 205, alpha), 1.2));
        painter.setBrush(QColor(255, 255, 255, active_ ? 40 : 16));
        painter.drawEllipse(c, r, r);
        painter.setBrush(Qt::NoBrush);
        painter.drawEllipse(c, r, r * 0.35); // the equator, seen from a little above
        const QPointF p(c.x() + r * x, c.y() - r * y);
        painter.setPen(QPen(QColor(255, 214, 90), 1.5));
        painter.drawLine(c, p);
        painter.setBrush(z >= 0.0 ? QBrush(QColor(255, 214, 90)) : QBrush(Qt::NoBrush));
        painter.drawEllipse(p, 4.5, 4.5);
        painter.setPen(QColor(200, 200, 205, alpha));
        QFont font = painter.font();
        font.setPointSizeF(font.pointSizeF() * 0.85);
        painter.setFont(font);
        painter.drawText(QRectF(0.0, c.y() + r + 4.0, width() - 4.0, 18.0), Qt::AlignRight | Qt::AlignTop,
                         MeshView::tr("Shift+drag: light"));
    }

  private:
    MeshView* view_;
    bool active_ = false;
};

namespace {


const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
uniform mat4 mvp;
uniform mat4 modelView;
uniform vec3 eye;        // world
uniform vec3 lightDir;   // world, toward the light (directional)
uniform vec3 lightPos;   // world (point light)
uniform bool lightIsPoint;
out vec3 viewNormal;
out float nDotL;         // the shadow and isophote function, per vertex as the engine samples it
out float rDotV;         // the gleam function
void main() {
    viewNormal = mat3(modelView) * normal;
    vec3 n = normalize(normal);
    vec3 l = lightIsPoint ? normalize(lightPos - position) : normalize(lightDir);
    vec3 v = normalize(eye - position);
    nDotL = dot(n, l);
    rDotV = dot(reflect(-l, n), v);
    gl_Position = mvp * vec4(position, 1.0);
}
)";

// Two-sided: open meshes show their inside, lit as well as the outside.
// With region colouring the surface takes the colour of its planar-map
// class (shadow, lit, isophote band, highlight), as region.h decides it,
// shaded lightly for form. The class rule and the arrays' sizes are put in
// by fragmentShader().
const char* kFragmentHead = R"(#version 330 core
in vec3 viewNormal;
in float nDotL;
in float rDotV;
uniform bool regions;
)";
const char* kFragmentMain = R"(
out vec4 colour;
void main() {
    vec3 n = normalize(viewNormal);
    if (!gl_FrontFacing) n = -n;
    float fill = 0.35 * max(n.z, 0.0); // a soft light from the viewer, so the side turned away keeps its form
    if (!regions) {
        // Lit by the document's light (N.L as the contours see it), not a
        // headlight: the shading turns as the light does.
        float lit = max(gl_FrontFacing ? nDotL : -nDotL, 0.0);
        vec3 base = vec3(0.80, 0.78, 0.74);
        colour = vec4(base * (0.12 + 0.72 * lit + fill), 1.0);
        return;
    }
    vec3 key = normalize(vec3(-0.5, 0.6, 0.65));
    float diffuse = max(dot(n, key), 0.0);
    vec3 c = classColour[regionClass(nDotL, rDotV)];
    colour = vec4(c * (0.72 + 0.2 * diffuse + 0.12 * fill), 1.0);
}
)";

/// The surface's fragment shader with room for @p bands and @p highlights levels.
QByteArray fragmentShader(int bands, int highlights) {
    return QByteArray(kFragmentHead) + QByteArray::fromStdString(region_class_glsl(bands, highlights)) +
           "uniform vec3 classColour[" + QByteArray::number(2 + std::max(bands, 1) + std::max(highlights, 1)) + "];\n" +
           kFragmentMain;
}

// Contours over the surface: hidden ones dashed by their arc length.
const char* kLineVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 colour;
layout(location = 2) in float hidden;
layout(location = 3) in float arc;
uniform mat4 mvp;
uniform float depthBias;
out vec3 lineColour;
out float lineHidden;
out float lineArc;
void main() {
    lineColour = colour;
    lineHidden = hidden;
    lineArc = arc;
    gl_Position = mvp * vec4(position, 1.0);
    gl_Position.z -= depthBias * gl_Position.w; // a line on the surface wins against it
}
)";

const char* kLineFragmentShader = R"(#version 330 core
in vec3 lineColour;
in float lineHidden;
in float lineArc;
uniform float dashLength;
out vec4 colour;
void main() {
    if (lineHidden > 0.5 && mod(lineArc, 2.0 * dashLength) > dashLength) discard;
    colour = vec4(lineColour, lineHidden > 0.5 ? 0.55 : 1.0);
}
)";

} // namespace

MeshView::MeshView(QWidget* parent) : QOpenGLWidget(parent), globe_(new LightGlobe(this)) {
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(200, 150);
    setToolTip(tr("The mesh with its contours (hidden parts dashed). Drag: orbit; Shift+drag: turn the light; "
                  "right or middle drag: pan; wheel: zoom; Home: reset the camera"));
}

void MeshView::resizeEvent(QResizeEvent* event) {
    QOpenGLWidget::resizeEvent(event);
    globe_->move(width() - globe_->width(), 0);
}

MeshView::~MeshView() {
    if (!glReady_) return;
    makeCurrent();
    vbo_.destroy();
    vao_.destroy();
    lineVbo_.destroy();
    lineVao_.destroy();
    doneCurrent();
}

namespace {

// Faces the view draws at most; 0: no limit. Set when the GL context shows
// a software renderer, which draws a million triangles in a sixth of a second.
std::atomic<std::size_t> face_budget{0};

} // namespace

std::size_t display_face_budget() { return face_budget.load(); }

MeshGeometry mesh_geometry(const MeshTopology& mesh, std::size_t max_faces) {
    MeshGeometry g;
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (const glm::dvec3& p : mesh.positions()) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    g.centre = mesh.n_vertices() ? 0.5 * (lo + hi) : glm::dvec3(0.0);
    g.radius = mesh.n_vertices() ? std::max(0.5 * glm::length(hi - lo), 1e-9) : 1.0;
    auto corner = [&g](const glm::dvec3& p, const glm::dvec3& n) {
        g.vertices.insert(g.vertices.end(), {float(p.x), float(p.y), float(p.z), float(n.x), float(n.y), float(n.z)});
    };
    if (max_faces == 0 || mesh.n_faces() <= max_faces) {
        g.vertices.reserve(mesh.n_faces() * 18);
        for (const auto& f : mesh.face_vertices())
            for (const VertexId v : f) corner(mesh.positions()[v], mesh.normals()[v]);
        return g;
    }
    // Vertex clustering on a uniform grid: each cell's vertices merge into
    // their mean, faces that collapse are dropped. Display only: contours
    // are always computed on the full mesh.
    const glm::dvec3 size = glm::max(hi - lo, glm::dvec3(1e-12));
    const double cells = std::cbrt(double(max_faces) * 0.5 * size.x * size.x / (size.y * size.z) + 1.0);
    const double cell = std::max(size.x / std::max(cells, 1.0), 1e-12);
    const glm::dvec3 dims = glm::ceil(size / cell) + 1.0;
    std::unordered_map<std::uint64_t, std::uint32_t> cluster_of_cell;
    VertexData<std::uint32_t> cluster(mesh.n_vertices());
    std::vector<glm::dvec3> sum_p, sum_n;
    for (const VertexId v : mesh.vertices()) {
        const glm::dvec3 q = glm::floor((mesh.positions()[v] - lo) / cell);
        const std::uint64_t key = std::uint64_t(q.x) + std::uint64_t(dims.x) * (std::uint64_t(q.y) + std::uint64_t(dims.y) * std::uint64_t(q.z));
        auto [it, inserted] = cluster_of_cell.try_emplace(key, std::uint32_t(sum_p.size()));
        if (inserted) sum_p.emplace_back(0.0), sum_n.emplace_back(0.0);
        cluster[v] = it->second;
        sum_p[it->second] += mesh.positions()[v];
        sum_n[it->second] += mesh.normals()[v];
    }
    std::vector<std::uint32_t> count(sum_p.size(), 0);
    for (const auto c : cluster) ++count[c];
    for (std::size_t c = 0; c < sum_p.size(); ++c) {
        sum_p[c] /= double(count[c]);
        const double len = glm::length(sum_n[c]);
        sum_n[c] = len > 0.0 ? sum_n[c] / len : glm::dvec3(0.0, 0.0, 1.0);
    }
    for (const auto& f : mesh.face_vertices()) {
        const std::uint32_t c[3] = {cluster[f[0]], cluster[f[1]], cluster[f[2]]};
        if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2]) continue;
        // Clustering can fold a face over; such slivers would show dark.
        const glm::dvec3 n = glm::cross(sum_p[c[1]] - sum_p[c[0]], sum_p[c[2]] - sum_p[c[0]]);
        if (glm::dot(n, sum_n[c[0]] + sum_n[c[1]] + sum_n[c[2]]) <= 0.0) continue;
        for (const auto i : c) corner(sum_p[i], sum_n[i]);
    }
    return g;
}

void MeshView::setMesh(const Mesh& mesh) { setGeometry(mesh_geometry(build_topology(mesh), display_face_budget())); }

void MeshView::setGeometry(MeshGeometry geometry) {
    vertices_ = std::move(geometry.vertices);
    vertexCount_ = static_cast<int>(vertices_.size() / 6);
    centre_ = geometry.centre;
    radius_ = geometry.radius;
    dirty_ = true;
    // A new file stands on +Y (import turns FBX and Collada files upright
    // from their own axes); the user's up axis was for the file before.
    orbit_.up = glm::dvec3(0.0, 1.0, 0.0);
    orbit_.centre = centre_;
    update(); // the document frames the new mesh: setOrbit
}

void MeshView::setPose(MeshGeometry geometry) {
    vertices_ = std::move(geometry.vertices);
    vertexCount_ = static_cast<int>(vertices_.size() / 6);
    dirty_ = true;
    update();
}

void MeshView::setRegionShading(RegionShading shading) {
    shading_ = std::move(shading);
    // Every level the style has is drawn: the shader grows to hold them.
    if (int(shading_.bands.size()) > bandCapacity_ || int(shading_.highlights.size()) > highlightCapacity_) {
        bandCapacity_ = std::max(bandCapacity_, int(shading_.bands.size()));
        highlightCapacity_ = std::max(highlightCapacity_, int(shading_.highlights.size()));
        programStale_ = true;
    }
    globe_->update(); // the light may have moved (a drag, an orbiting light's frame)
    update();
}

void MeshView::setRegionUniforms() {
    const RegionShading& r = shading_;
    auto vec = [](const glm::dvec3& v) { return QVector3D(float(v.x), float(v.y), float(v.z)); };
    auto rgb = [](const glm::vec3& v) { return QVector3D(v.x, v.y, v.z); };
    auto at = [](const char* name, std::size_t i) { return QString("%1[%2]").arg(name).arg(i).toLatin1(); };
    program_.setUniformValue("regions", r.enabled);
    program_.setUniformValue("eye", vec(camera().eye));
    program_.setUniformValue("lightDir", vec(r.light.dir));
    program_.setUniformValue("lightPos", vec(r.light.pos));
    program_.setUniformValue("lightIsPoint", r.light.point);
    // Classes as ShadingClasses numbers them: shadow, lit, bands, highlights.
    program_.setUniformValue("hasShadow", r.shadow_contour);
    program_.setUniformValue("bandCount", int(r.bands.size()));
    program_.setUniformValue("highlightCount", int(r.highlights.size()));
    program_.setUniformValue(at("classColour", 0).constData(), rgb(r.shadow));
    program_.setUniformValue(at("classColour", 1).constData(), rgb(r.lit));
    for (std::size_t i = 0; i < r.bands.size(); ++i) {
        program_.setUniformValue(at("bandK", i).constData(), float(r.bands[i].first));
        program_.setUniformValue(at("classColour", 2 + i).constData(), rgb(r.bands[i].second));
    }
    for (std::size_t i = 0; i < r.highlights.size(); ++i) {
        program_.setUniformValue(at("highlightK", i).constData(), float(r.highlights[i].first));
        program_.setUniformValue(at("classColour", 2 + r.bands.size() + i).constData(), rgb(r.highlights[i].second));
    }
}

void MeshView::buildSurfaceProgram() {
    program_.removeAllShaders();
    program_.addShaderFromSourceCode(QOpenGLShader::Vertex, kVertexShader);
    program_.addShaderFromSourceCode(QOpenGLShader::Fragment, fragmentShader(bandCapacity_, highlightCapacity_));
    program_.link();
    programStale_ = false;
}

void MeshView::clearMesh() {
    vertices_.clear();
    vertexCount_ = 0;
    dirty_ = true;
    setContours({}, camera());
}

void MeshView::setContours(std::vector<ContourStrip> strips, const Camera& seenFrom) {
    strips_ = std::move(strips);
    contourCamera_ = seenFrom;
    linesDirty_ = true;
    update();
}

Camera MeshView::camera() const { return fileCamera_ ? *fileCamera_ : orbit_camera(orbit_); }

void MeshView::setFileCamera(const std::optional<Camera>& camera) {
    if (fileCamera_ == camera) return;
    fileCamera_ = camera;
    update();
}

Camera MeshView::baseCamera() const { return orbit_base_camera(orbit_); }

void MeshView::setOrbit(const OrbitView& orbit) {
    const double turntable = orbit_.turntable;
    orbit_ = orbit;
    orbit_.centre = centre_; // the mesh's, whatever was saved
    orbit_.turntable = turntable;
    update();
    emit cameraChanged();
}

void MeshView::uploadContours() {
    lineVertices_.clear();
    lineRanges_.clear();
    for (const ContourStrip& s : strips_) {
        if (s.points.size() < 2) continue;
        const int first = static_cast<int>(lineVertices_.size() / 8);
        float arc = 0.0f;
        const std::size_t n = s.points.size() + (s.closed ? 1 : 0);
        for (std::size_t i = 0; i < n; ++i) {
            const glm::vec3 p = s.points[i % s.points.size()];
            if (i) arc += glm::length(p - s.points[(i - 1) % s.points.size()]);
            lineVertices_.insert(lineVertices_.end(), {p.x, p.y, p.z, s.colour.x, s.colour.y, s.colour.z,
                                                       s.hidden ? 1.0f : 0.0f, arc});
        }
        lineRanges_.push_back({first, static_cast<int>(n)});
    }
    uploadLineVertices(lineVao_, lineVbo_, lineVertices_);
    linesDirty_ = false;
}

void MeshView::uploadLineVertices(QOpenGLVertexArrayObject& vao, QOpenGLBuffer& vbo, const std::vector<float>& data) {
    QOpenGLVertexArrayObject::Binder bind(&vao);
    vbo.bind();
    vbo.allocate(data.data(), static_cast<int>(data.size() * sizeof(float)));
    const int stride = 8 * sizeof(float);
    for (int a = 0; a < 4; ++a) glEnableVertexAttribArray(GLuint(a));
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(3 * sizeof(float)));
    glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(6 * sizeof(float)));
    glVertexAttribPointer(3, 1, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(7 * sizeof(float)));
    vbo.release();
}

void MeshView::setTurntable(double degrees) {
    orbit_.turntable = glm::radians(degrees);
    update();
    emit cameraChanged();
}

void MeshView::centreView() {
    if (orbit_.pan == glm::dvec3(0.0)) return;
    orbit_.pan = glm::dvec3(0.0);
    update();
    emit cameraChanged();
}

void MeshView::resetCamera() { frame(drawnPoints()); }

std::vector<glm::vec3> MeshView::drawnPoints() const {
    // The pose drawn (a clip's frame may stand far from the rest pose).
    std::vector<glm::vec3> points;
    points.reserve(vertices_.size() / 6);
    for (std::size_t i = 0; i + 5 < vertices_.size(); i += 6) points.emplace_back(vertices_[i], vertices_[i + 1], vertices_[i + 2]);
    return points;
}

OrbitView MeshView::poseFraming() const { return framing(drawnPoints()); }

void MeshView::frameSelected() {
    if (highlight_.empty()) resetCamera();
    else frame(highlight_);
}

void MeshView::frame(const std::vector<glm::vec3>& points) {
    orbit_ = framing(points);
    update();
    emit cameraChanged();
    emit viewEdited();
}

OrbitView MeshView::framing(const std::vector<glm::vec3>& points) const {
    // The model's front from a little above and to the side, standing on its
    // up axis, framing the points' bounding sphere, reached by a pan from
    // the orbit's centre, which stays the mesh's (turntables turn about it).
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (const glm::vec3& p : points) {
        lo = glm::min(lo, glm::dvec3(p));
        hi = glm::max(hi, glm::dvec3(p));
    }
    const bool any = !points.empty();
    const glm::dvec3 centre = any ? 0.5 * (lo + hi) : centre_;
    const double radius = any ? std::max(0.5 * glm::length(hi - lo), 1e-9) : radius_;
    // Home keeps the projection and the lens, as Blender's does.
    OrbitView v = framing_view(centre_, radius, orbit_.up);
    v.orthographic = orbit_.orthographic;
    v.fov_deg = orbit_.fov_deg;
    v.distance = framing_distance(radius, v.fov_deg);
    glm::dvec3 right, up;
    orbit_camera(v).screen_basis(right, up);
    // In eye space the pan adds to the offset from the centre: it cancels the pose's.
    v.pan = -glm::dvec3(glm::dot(centre - centre_, right), glm::dot(centre - centre_, up), 0.0);
    v.turntable = orbit_.turntable;
    return v;
}

void MeshView::initializeGL() {
    initializeOpenGLFunctions();
    const QString renderer = QString::fromLatin1(reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
    if (renderer.contains("llvmpipe", Qt::CaseInsensitive) || renderer.contains("softpipe", Qt::CaseInsensitive) ||
        renderer.contains("SwiftShader", Qt::CaseInsensitive))
        face_budget = 250'000;
    buildSurfaceProgram();
    lineProgram_.addShaderFromSourceCode(QOpenGLShader::Vertex, kLineVertexShader);
    lineProgram_.addShaderFromSourceCode(QOpenGLShader::Fragment, kLineFragmentShader);
    lineProgram_.link();
    vao_.create();
    vbo_.create();
    lineVao_.create();
    lineVbo_.create();
    highlightVao_.create();
    highlightVbo_.create();
    frameVao_.create();
    frameVbo_.create();
    highlightDirty_ = true;
    glReady_ = true;
    dirty_ = true;
}

void MeshView::upload() {
    QOpenGLVertexArrayObject::Binder bind(&vao_);
    vbo_.bind();
    vbo_.allocate(vertices_.data(), static_cast<int>(vertices_.size() * sizeof(float)));
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float),
                          reinterpret_cast<void*>(3 * sizeof(float)));
    vbo_.release();
    dirty_ = false;
}

glm::dmat4 MeshView::viewMatrix() const {
    if (!fileCamera_) return orbit_view_matrix(orbit_);
    const Camera& c = *fileCamera_;
    glm::dvec3 right, up;
    c.screen_basis(right, up);
    return glm::lookAt(c.eye, c.eye + c.forward(), up);
}

void MeshView::setCanvas(int width, int height, double margin, const Page& page) {
    if (canvas_.width == width && canvas_.height == height && canvas_.margin == margin && canvas_.page == page) return;
    canvas_.width = width;
    canvas_.height = height;
    canvas_.margin = margin;
    canvas_.page = page;
    update();
}

void MeshView::setFrameShown(bool shown) {
    if (frameShown_ == shown) return;
    frameShown_ = shown;
    update();
}

QRectF MeshView::frameRect() const {
    const double s = frameScale(), w = canvas_.width * s, h = canvas_.height * s;
    return {0.5 * (width() - w), 0.5 * (height() - h), w, h};
}

double MeshView::frameScale() const {
    // A little room around the frame, so its border shows.
    const double room = 12.0;
    return std::max(std::min((width() - 2.0 * room) / canvas_.width, (height() - 2.0 * room) / canvas_.height), 1e-3);
}

ImageProjection MeshView::drawingProjection() const {
    return drawing_projection(canvas_, camera(), centre_, radius_);
}

double MeshView::worldPerPixel() const {
    const Camera c = camera();
    const double px = frameScale() * drawingProjection().scale(); // view pixels per unit (at unit depth)
    if (c.orthographic()) return 1.0 / px;
    return (fileCamera_ ? std::max(glm::dot(centre_ - c.eye, c.forward()), 1e-9) : orbit_.distance) / px;
}

glm::dmat4 MeshView::projectionMatrix() const {
    // As the drawing projects onto its canvas, the canvas scaled into the
    // frame at the view's centre: the same picture.
    const Camera c = camera();
    const double aspect = double(std::max(width(), 1)) / std::max(height(), 1);
    const double px = frameScale() * drawingProjection().scale(); // view pixels per unit (at unit depth)
    const double half = 0.5 * std::max(height(), 1) / px;         // the view's half height (at unit depth)
    const double depth = glm::dot(centre_ - c.eye, c.forward());
    const double far = std::max(depth + radius_ * 1.5, radius_ * 1e-3);
    if (c.orthographic()) return glm::ortho(-half * aspect, half * aspect, -half, half, depth - radius_ * 1.5, far);
    // Nothing nearer than the camera's near plane, as the drawing clips there.
    const double near = std::max({depth - radius_ * 1.5, far * 1e-4, c.near_plane(radius_)});
    return glm::perspective(2.0 * std::atan(half), aspect, near, far);
}

void MeshView::drawFrame() {
    // In normalized device coordinates, through the line shader: the four
    // bands outside the frame darkened (its translucent "hidden" colour
    // without dashes), then the frame's border.
    const QRectF f = frameRect();
    const float w = float(std::max(width(), 1)), h = float(std::max(height(), 1));
    const float l = float(2.0 * f.left() / w - 1.0), r = float(2.0 * f.right() / w - 1.0);
    const float t = float(1.0 - 2.0 * f.top() / h), b = float(1.0 - 2.0 * f.bottom() / h);
    std::vector<float> data;
    auto corner = [&](float x, float y, float grey, float translucent) {
        data.insert(data.end(), {x, y, 0.0f, grey, grey, grey, translucent, 0.0f});
    };
    auto quad = [&](float x0, float y0, float x1, float y1) {
        for (const auto& [x, y] : {std::pair{x0, y0}, {x1, y0}, {x1, y1}, {x0, y0}, {x1, y1}, {x0, y1}}) corner(x, y, 0.0f, 1.0f);
    };
    quad(-1.0f, t, 1.0f, 1.0f);  // above
    quad(-1.0f, -1.0f, 1.0f, b); // below
    quad(-1.0f, b, l, t);        // left
    quad(r, b, 1.0f, t);         // right
    for (const auto& [x, y] : {std::pair{l, t}, {r, t}, {r, b}, {l, b}}) corner(x, y, 0.78f, 0.0f);
    uploadLineVertices(frameVao_, frameVbo_, data);
    QOpenGLVertexArrayObject::Binder bind(&frameVao_);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    lineProgram_.bind();
    const glm::mat4 identity(1.0f);
    glUniformMatrix4fv(lineProgram_.uniformLocation("mvp"), 1, GL_FALSE, glm::value_ptr(identity));
    lineProgram_.setUniformValue("dashLength", 1e30f);
    lineProgram_.setUniformValue("depthBias", 0.0f);
    glDrawArrays(GL_TRIANGLES, 0, 24);
    glDrawArrays(GL_LINE_LOOP, 24, 4);
    lineProgram_.release();
    glDisable(GL_BLEND);
}

void MeshView::paintGL() {
    globe_->update(); // the camera or the light may have turned
    // The frame's painter leaves its own state: set what the drawing needs.
    glViewport(0, 0, int(width() * devicePixelRatioF()), int(height() * devicePixelRatioF()));
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_STENCIL_TEST);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glClearColor(0.16f, 0.17f, 0.19f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (!vertexCount_) return;
    if (dirty_) upload();
    glEnable(GL_DEPTH_TEST);
    if (programStale_) buildSurfaceProgram(); // more levels than its arrays hold
    const glm::mat4 mv(viewMatrix());
    const glm::mat4 mvp(projectionMatrix() * viewMatrix());
    program_.bind();
    glUniformMatrix4fv(program_.uniformLocation("mvp"), 1, GL_FALSE, glm::value_ptr(mvp));
    glUniformMatrix4fv(program_.uniformLocation("modelView"), 1, GL_FALSE, glm::value_ptr(mv));
    setRegionUniforms();
    {
        QOpenGLVertexArrayObject::Binder bind(&vao_);
        glDrawArrays(GL_TRIANGLES, 0, vertexCount_);
    }
    program_.release();
    drawHighlight(mvp);

    // Contours seen from this camera: their visibility is known, so no
    // depth test, hidden parts first. Contours of an earlier camera (an
    // orbit under way, their successors not yet computed) are drawn where
    // they lie on the surface, against the surface's depth: what turned
    // behind the mesh is hidden by it instead of crossing its face.
    if (linesDirty_) uploadContours();
    if (!lineRanges_.empty()) drawContours(mvp, contoursStale());
    if (frameShown_) drawFrame();
}

void MeshView::setHighlight(std::vector<glm::vec3> triangles) {
    highlight_ = std::move(triangles);
    highlightDirty_ = true;
    update();
}

void MeshView::drawHighlight(const glm::mat4& mvp) {
    if (highlightDirty_) {
        // The line shader's layout (position, colour, hidden, arc): a hidden
        // flag without dashes draws the tint translucent.
        std::vector<float> data;
        data.reserve(highlight_.size() * 8);
        for (const glm::vec3& p : highlight_) data.insert(data.end(), {p.x, p.y, p.z, 1.0f, 0.55f, 0.1f, 1.0f, 0.0f});
        uploadLineVertices(highlightVao_, highlightVbo_, data);
        highlightVertices_ = static_cast<int>(highlight_.size());
        highlightDirty_ = false;
    }
    if (highlightVertices_ == 0) return;
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    lineProgram_.bind();
    glUniformMatrix4fv(lineProgram_.uniformLocation("mvp"), 1, GL_FALSE, glm::value_ptr(mvp));
    lineProgram_.setUniformValue("dashLength", 1e30f);
    lineProgram_.setUniformValue("depthBias", 2e-4f);
    {
        QOpenGLVertexArrayObject::Binder bind(&highlightVao_);
        glDrawArrays(GL_TRIANGLES, 0, highlightVertices_);
    }
    lineProgram_.release();
    glDisable(GL_BLEND);
    glDepthFunc(GL_LESS);
}

bool MeshView::contoursStale() const { return !(contourCamera_ == camera()); }

void MeshView::drawContours(const glm::mat4& mvp, bool stale) {
    if (stale) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
    } else {
        glDisable(GL_DEPTH_TEST);
    }
    glEnable(GL_BLEND);
    // Blend colour only: the widget composites its framebuffer as
    // premultiplied, so its alpha must stay opaque.
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    lineProgram_.bind();
    glUniformMatrix4fv(lineProgram_.uniformLocation("mvp"), 1, GL_FALSE, glm::value_ptr(mvp));
    // Dashes of about 6 pixels at the mesh's distance.
    lineProgram_.setUniformValue("dashLength", float(6.0 * worldPerPixel()));
    lineProgram_.setUniformValue("depthBias", stale ? 2e-4f : 0.0f);
    QOpenGLVertexArrayObject::Binder bind(&lineVao_);
    for (const bool hiddenPass : {true, false}) {
        if (stale && hiddenPass) continue; // what was hidden then may show now: the depth test decides
        for (std::size_t i = 0, r = 0; i < strips_.size(); ++i) {
            if (strips_[i].points.size() < 2) continue;
            if (strips_[i].hidden == hiddenPass) glDrawArrays(GL_LINE_STRIP, lineRanges_[r].first, lineRanges_[r].second);
            ++r;
        }
    }
    lineProgram_.release();
    glDisable(GL_BLEND);
    glDepthFunc(GL_LESS);
}

void MeshView::mousePressEvent(QMouseEvent* event) {
    lastPos_ = event->position().toPoint();
    pressed_ = true;
    dragged_ = false;
    draggingLight_ = (event->button() == Qt::LeftButton) && (event->modifiers() & Qt::ShiftModifier);
    if (draggingLight_) globe_->setActive(true); // the light's globe brightens while it turns
}

void MeshView::mouseReleaseEvent(QMouseEvent* event) {
    const bool pressed = std::exchange(pressed_, false);
    if (!pressed || !dragged_) {
        draggingLight_ = false;
        globe_->setActive(false);
        return;
    }
    dragged_ = false;
    draggingLight_ = false;
    globe_->setActive(false);
    event->accept();
}

void MeshView::mouseMoveEvent(QMouseEvent* event) {
    const QPoint pos = event->position().toPoint();
    const QPoint d = pos - lastPos_;
    lastPos_ = pos;
    if (d.isNull() || !pressed_) return; // a hover, or a drag that began elsewhere
    dragged_ = true;
    if (draggingLight_ && (event->buttons() & Qt::LeftButton)) {
        // Screen-space rotation of the light: right turns it about the
        // screen's up axis, down about its right axis.
        glm::dvec3 right, up;
        camera().screen_basis(right, up);
        emit lightDragged(up, d.x() * 0.01, right, d.y() * 0.01);
        return;
    }
    if (fileCamera_ && (event->buttons() & (Qt::LeftButton | Qt::RightButton | Qt::MiddleButton))) {
        emit lockedToFileCamera();
        return;
    }
    const OrbitView before = orbit_;
    if (event->buttons() & Qt::LeftButton) {
        orbit_.yaw += d.x() * 0.01;
        orbit_.pitch = std::clamp(orbit_.pitch + d.y() * 0.01, -kMaxPitch, kMaxPitch);
    } else if (event->buttons() & (Qt::RightButton | Qt::MiddleButton)) {
        const double perPixel = worldPerPixel(); // the grabbed point follows the cursor
        orbit_.pan += glm::dvec3(d.x() * perPixel, -d.y() * perPixel, 0.0);
    } else {
        return;
    }
    if (orbit_ == before) return; // pitched against its limit: nothing moved, no edit
    update();
    emit cameraChanged();
    emit viewEdited();
}

void MeshView::wheelEvent(QWheelEvent* event) {
    if (fileCamera_) {
        emit lockedToFileCamera();
        return;
    }
    const double steps = event->angleDelta().y() / 120.0;
    orbit_.distance = std::clamp(orbit_.distance * std::pow(0.85, steps), radius_ * 0.05, radius_ * 100.0);
    update();
    emit cameraChanged();
    emit viewEdited();
}

} // namespace snaxels::ui
