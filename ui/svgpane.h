#pragma once
// The SVG pane: the current frame drawn from the very SVG that export
// writes, on a page the size of its canvas (nothing drawn past the page's
// edge, as in the file), fitted to the pane; the wheel zooms about the
// pointer, a drag pans, a double click fits it again.

#include <QByteArray>
#include <QPointF>
#include <QString>
#include <QSvgRenderer>
#include <QWidget>

class QPainter;

namespace snaxels::ui {

class SvgPane : public QWidget {
    Q_OBJECT
  public:
    explicit SvgPane(QWidget* parent = nullptr);

    /// Shows @p svg, keeping the zoom and pan; false if it does not parse.
    bool load(const QByteArray& svg);
    /// The frame the pane is for cannot be drawn: the last drawing stays,
    /// faded, under @p problem (until the next load).
    void setProblem(const QString& problem);
    const QString& problem() const { return problem_; }
    QSvgRenderer* renderer() { return &renderer_; }
    double zoom() const { return zoom_; }
    QPointF offset() const { return offset_; }
    /// Zooms by @p factor keeping the drawing point under @p anchor (widget
    /// coordinates) in place.
    void zoomAt(double factor, QPointF anchor);
    /// Fits the whole drawing again.
    void fit();
    /// Where the drawing lies in the widget now.
    QRectF drawingRect() const;

  protected:
    void paintEvent(QPaintEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;

  private:
    QRectF fittedRect() const;
    void paintPage(QPainter& painter);

    QSvgRenderer renderer_;
    double zoom_ = 1.0;
    QPointF offset_; ///< pan in widget pixels
    QPointF lastPos_;
    QString problem_;
};

} // namespace snaxels::ui
