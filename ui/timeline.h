#pragma once
// The timeline: what moves (turntable, orbiting light, nothing, one of the
// mesh's own clips, a sequence of mesh files or one of the file's cameras),
// which camera looks (the view's or one of the file's), how far per frame,
// how many frames at what rate, the current frame, play/pause and loop.

#include <deque>

#include <QElapsedTimer>
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
    /// The file's cameras: offered to look through (the camera box), and
    /// those a clip moves also as sources ("Camera: NAME", the mesh still).
    void setCameras(const std::vector<FileCamera>& cameras);
    int frame() const;
    /// The source's frame shown now: the in point plus the current frame.
    int sourceFrame() const;
    void setFrame(int frame);
    void setFrameCount(int frames);
    bool playing() const { return timer_.isActive(); }
    /// Play shows every frame, however long each takes (else, the default,
    /// it drops the frames it cannot show in time, as a video player does).
    bool playsEveryFrame() const;
    void setPlaysEveryFrame(bool every);
    /// Frames a second the preview showed over the last second of play
    /// (0 when not playing or nothing was shown yet).
    double shownRate() const { return shownRate_; }

    /// Takes up a value typed in a box and not yet entered (typed values
    /// take effect on Enter or when the box is left): before a save, an
    /// export or an undo, what the box shows is what counts.
    void applyPending();

  public slots:
    void togglePlay();
    void step(int delta);
    /// The view now shows frame @p frame (its contours arrived): the
    /// achieved rate counts it, and a play of every frame goes on from it.
    void frameShown(int frame);

  signals:
    /// The current frame or the animation settings changed.
    void changed();
    /// The user changed the animation settings (source, degrees, frames,
    /// rate): one step for the undo stack.
    void specEdited();
    /// How play keeps up, for the status bar (empty when it stops).
    void playbackStatus(const QString& text);

  private:
    /// The widgets' ranges, texts and tips, and their layout.
    void setUpWidgets();
    /// What each widget's change does (in the order the widgets signal).
    void connectWidgets();
    void advance();
    /// The frame after @p frame, or -1 at the end without loop.
    int nextFrame(int frame) const;
    void updateRate();
    void edited();
    void updateEnabled();

    QComboBox* source_;
    QComboBox* camera_;
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
    QCheckBox* everyFrame_;
    QTimer timer_;
    // Play keeps time by a clock: the frame due now is the one it started
    // at plus the time played times the rate.
    QElapsedTimer clock_;
    qint64 clockStartFrame_ = 0, clockStartNs_ = 0;
    bool advancing_ = false; ///< the clock moves the frame (not the user)
    /// The clock goes on from the current frame, now.
    void anchorClock();
    qint64 lastStepNs_ = 0;        ///< every-frame play: when it last stepped
    int lastShown_ = -1;            ///< the frame shown last
    std::deque<qint64> shownAt_;    ///< when frames were shown (ns on clock_), the last second
    qint64 rateAt_ = 0;             ///< when the rate was last worked out
    double shownRate_ = 0.0;
    QString status_;
    int quiet_ = 0; ///< set while showing a spec: no specEdited
};

} // namespace snaxels::ui
