#pragma once
// The timeline: what moves (turntable or orbiting light), how far per frame,
// how many frames at what rate, the current frame, play/pause and loop.

#include <QTimer>
#include <QWidget>

#include "core/scene/animation.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSlider;
class QSpinBox;

namespace snaxels::ui {

class Timeline : public QWidget {
    Q_OBJECT
  public:
    explicit Timeline(QWidget* parent = nullptr);

    /// Source, degrees per frame, frame count and rate.
    AnimationSpec spec() const;
    int frame() const;
    void setFrame(int frame);
    void setFrameCount(int frames);
    bool playing() const { return timer_.isActive(); }

  public slots:
    void togglePlay();
    void step(int delta);

  signals:
    /// The current frame or the animation settings changed.
    void changed();

  private:
    void advance();

    QComboBox* source_;
    QDoubleSpinBox* degrees_;
    QSpinBox* frames_;
    QDoubleSpinBox* fps_;
    QSlider* slider_;
    QLabel* label_;
    QPushButton* play_;
    QCheckBox* loop_;
    QTimer timer_;
};

} // namespace snaxels::ui
