#include "ui/svgpane.h"

#include <algorithm>
#include <cmath>

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

namespace snaxels::ui {

SvgPane::SvgPane(QWidget* parent) : QWidget(parent) {
    setMinimumSize(200, 200);
    setProblem({});
    setCursor(Qt::OpenHandCursor);
}

bool SvgPane::load(const QByteArray& svg) {
    setProblem({});
    const bool ok = renderer_.load(svg);
    renderer_.setAspectRatioMode(Qt::KeepAspectRatio);
    update();
    return ok;
}

void SvgPane::setProblem(const QString& problem) {
    problem_ = problem;
    setToolTip(!problem.isEmpty() ? problem : tr("The exported SVG of this frame. Wheel: zoom, drag: pan, double click: fit"));
    update();
}

QRectF SvgPane::fittedRect() const {
    QSizeF size = renderer_.viewBoxF().size();
    if (size.isEmpty()) size = renderer_.defaultSize();
    if (size.isEmpty()) return rect();
    const QSizeF fitted = size.scaled(QSizeF(width(), height()), Qt::KeepAspectRatio);
    return QRectF(QPointF((width() - fitted.width()) / 2, (height() - fitted.height()) / 2), fitted);
}

QRectF SvgPane::drawingRect() const {
    const QRectF f = fittedRect();
    const QPointF centre = QPointF(width() / 2.0, height() / 2.0);
    return QRectF(centre + (f.topLeft() - centre) * zoom_ + offset_, f.size() * zoom_);
}

void SvgPane::zoomAt(double factor, QPointF anchor) {
    const double zoom = std::clamp(zoom_ * factor, 0.1, 64.0);
    factor = zoom / zoom_;
    // Keep the drawing point under the anchor fixed: p' = c + (p - c) * z + o.
    const QPointF centre(width() / 2.0, height() / 2.0);
    offset_ = anchor - centre - (anchor - centre - offset_) * factor;
    zoom_ = zoom;
    update();
}

void SvgPane::fit() {
    zoom_ = 1.0;
    offset_ = {};
    update();
}

void SvgPane::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.fillRect(rect(), palette().window());
    if (renderer_.isValid()) paintPage(painter);
    if (problem_.isEmpty()) return;
    // Over a faded drawing of another frame (or nothing): why this one is missing.
    if (renderer_.isValid()) painter.fillRect(rect(), QColor(255, 255, 255, 190));
    const QRectF box = QRectF(rect()).adjusted(24, 24, -24, -24);
    painter.setPen(palette().color(QPalette::WindowText));
    painter.drawText(box, Qt::AlignCenter | Qt::TextWordWrap, problem_);
}

void SvgPane::paintPage(QPainter& painter) {
    // The page, as the exported file shows it: what lies past its canvas
    // (strokes and fills near the edge) is clipped away, as a viewer of the
    // file clips it; the page's edge is drawn round it.
    const QRectF page = drawingRect();
    painter.fillRect(page.translated(2.0, 2.0), QColor(0, 0, 0, 50)); // its shadow
    painter.fillRect(page, Qt::white); // a transparent canvas shows as paper
    painter.save();
    painter.setClipRect(page);
    painter.setRenderHint(QPainter::Antialiasing);
    renderer_.render(&painter, page);
    painter.restore();
    painter.setPen(QPen(QColor(0, 0, 0, 120), 1.0));
    painter.drawRect(page);
}

void SvgPane::wheelEvent(QWheelEvent* event) {
    zoomAt(std::pow(1.2, event->angleDelta().y() / 120.0), event->position());
    event->accept();
}

void SvgPane::mousePressEvent(QMouseEvent* event) {
    lastPos_ = event->position();
    setCursor(Qt::ClosedHandCursor);
}

void SvgPane::mouseMoveEvent(QMouseEvent* event) {
    if (!(event->buttons() & (Qt::LeftButton | Qt::MiddleButton))) {
        setCursor(Qt::OpenHandCursor);
        return;
    }
    offset_ += event->position() - lastPos_;
    lastPos_ = event->position();
    update();
}

void SvgPane::mouseDoubleClickEvent(QMouseEvent*) { fit(); }

} // namespace snaxels::ui
