#pragma once
// The timeline: what moves (turntable, orbiting light, nothing, one of the
// mesh's own clips or a sequence of mesh files), how far per frame,
// how many frames at what rate, the current frame, play/pause and loop.

#include <QTimer>
#include <QWidget>

#include "snaxels/mesh/mesh_animation.h"
#include "snaxels/animation/frame_driver.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSlider;
class QSpinBox;

namespace snaxels::ui {

/// The animation a new mesh starts with: a turntable of 180 frames at 2
/// degrees a frame (one turn) and 24 frames a second.
AnimationSpec initial_animation();

class Timeline : public QWidget {
    Q_OBJECT
  public:
    explicit Timeline(QWidget* parent = nullptr);

    /// Source, degrees per frame, frame count and rate.
    AnimationSpec spec() const;
    /// Shows @p spec (an undo step or a project); a clip the mesh lacks
    /// falls back to the turntable and returns false. A sequence becomes
    /// the source offered (in place of any other sequence).
    bool setSpec(const AnimationSpec& spec);
    /// How many files the sequence shown has (its length when chosen again).
    void setSequenceFiles(int count);
    /// The loaded mesh's own clips (name, seconds), offered as sources.
    void setClips(const std::vector<AnimationClipInfo>& clips);
    int frame() const;
    /// The source's frame shown now: the in point plus the current frame.
    int sourceFrame() const;
    void setFrame(int frame);
    void setFrameCount(int frames);
    bool playing() const { return timer_.isActive(); }

  public slots:
    void togglePlay();
    void step(int delta);

  signals:
    /// The current frame or the animation settings changed.
    void changed();
    /// The user changed the animation settings (source, degrees, frames,
    /// rate): one step for the undo stack.
    void specEdited();

  private:
    void advance();
    void edited();
    void updateEnabled();

    QComboBox* source_;
    QDoubleSpinBox* degrees_;
    QSpinBox* frames_;
    QSpinBox* start_;
    QDoubleSpinBox* fps_;
    QSlider* slider_;
    QSpinBox* frameBox_; ///< the current frame, typed
    QLabel* label_;      ///< the last frame and the time
    /// Shows the current frame in the box and the label (frame and seconds).
    void showPosition();
    QPushButton* play_;
    QCheckBox* loop_;
    QTimer timer_;
    int quiet_ = 0; ///< set while showing a spec: no specEdited
};

} // namespace snaxels::ui
