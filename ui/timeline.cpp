#include "ui/timeline.h"

#include <algorithm>
#include <cmath>

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QVBoxLayout>
#include <QLabel>
#include <QProxyStyle>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>

namespace snaxels::ui {
namespace {
constexpr int kKindRole = Qt::UserRole;
constexpr int kClipRole = Qt::UserRole + 1;
constexpr int kSecondsRole = Qt::UserRole + 2;
constexpr int kPatternRole = Qt::UserRole + 3; // a sequence's pattern
constexpr int kFirstRole = Qt::UserRole + 4;   // its first file's number
constexpr int kCountRole = Qt::UserRole + 5;   // its files (0: unknown)
constexpr int kCameraRole = Qt::UserRole + 6;  // a camera source's camera
} // namespace

namespace {

/// A click on the slider's track moves to the click, not a page toward it.
class JumpSliderStyle : public QProxyStyle {
  public:
    int styleHint(StyleHint hint, const QStyleOption* option, const QWidget* widget,
                  QStyleHintReturn* returned) const override {
        if (hint == QStyle::SH_Slider_AbsoluteSetButtons) return int(Qt::LeftButton | Qt::MiddleButton);
        return QProxyStyle::styleHint(hint, option, widget, returned);
    }
};

} // namespace

AnimationSpec initial_animation() {
    AnimationSpec spec;
    spec.kind = AnimationSpec::Kind::Turntable;
    spec.degrees_per_frame = 2.0;
    spec.frames = 180;
    spec.fps = 24.0;
    return spec;
}

Timeline::Timeline(QWidget* parent)
    : QWidget(parent), source_(new QComboBox(this)), camera_(new QComboBox(this)), degrees_(new QDoubleSpinBox(this)), frames_(new QSpinBox(this)),
      start_(new QSpinBox(this)), fps_(new QDoubleSpinBox(this)), slider_(new QSlider(Qt::Horizontal, this)),
      frameBox_(new QSpinBox(this)), label_(new QLabel(this)),
      play_(new QPushButton(tr("Play"), this)), loop_(new QCheckBox(tr("Loop"), this)),
      everyFrame_(new QCheckBox(tr("Every frame"), this)) {
    setClips({});
    setUpWidgets();
    connectWidgets();
    // The clock says which frame is due; the ticks only look at it, often
    // enough to show each frame within a few milliseconds of its time.
    timer_.setTimerType(Qt::PreciseTimer);
    timer_.setInterval(5);
    showPosition();
}

void Timeline::setUpWidgets() {
    camera_->setObjectName("cameraChoice");
    source_->setObjectName("source");
    degrees_->setObjectName("degreesPerFrame");
    camera_->addItem(tr("View camera"), QString());
    camera_->setToolTip(tr("The camera the frames are seen through: the view's (orbit with the mouse), or one of "
                           "the file's, with its field of view and aspect (a camera the file animates moves with "
                           "its clip)"));
    camera_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    camera_->setVisible(false); // until a file has cameras
    source_->setToolTip(tr("What moves from frame to frame"));
    source_->setSizeAdjustPolicy(QComboBox::AdjustToContents); // clip and sequence names in full
    degrees_->setRange(-90.0, 90.0);
    degrees_->setDecimals(2);
    degrees_->setValue(initial_animation().degrees_per_frame);
    degrees_->setSuffix(tr("°/frame"));
    frames_->setRange(1, 100000);
    frames_->setValue(initial_animation().frames);
    frames_->setSuffix(tr(" frames"));
    start_->setRange(0, 1000000);
    start_->setPrefix(tr("from "));
    start_->setToolTip(tr("In point: the source's frame the animation begins at"));
    fps_->setRange(1.0, 240.0);
    fps_->setValue(initial_animation().fps);
    fps_->setSuffix(tr(" fps"));
    slider_->setRange(0, frames_->value() - 1);
    loop_->setChecked(true);
    play_->setCheckable(true);
    degrees_->setToolTip(tr("How far the camera (turntable) or the light (orbiting light) turns each frame"));
    frames_->setToolTip(tr("How many frames the animation has"));
    fps_->setToolTip(tr("Frames a second, in the preview and in the exported animation"));
    play_->setToolTip(tr("Play or pause the preview (Space)"));
    loop_->setToolTip(tr("Start again at the first frame after the last"));
    everyFrame_->setToolTip(tr("Show every frame even when the preview cannot keep up (it then plays slower than "
                               "real time); off, frames that cannot be shown in time are dropped to keep time"));
    slider_->setToolTip(tr("The current frame: click or drag to scrub (Left and Right step a frame)"));
    auto* jump = new JumpSliderStyle;
    jump->setParent(slider_);
    slider_->setStyle(jump);
    frameBox_->setRange(0, frames_->value() - 1);
    frameBox_->setPrefix(tr("frame "));
    frameBox_->setToolTip(tr("The current frame: type one and press Enter"));
    frameBox_->setKeyboardTracking(false);
    label_->setToolTip(tr("The last frame, the current frame's time in seconds and, while playing, how many "
                          "frames a second the preview shows"));
    // Typed values take effect on Enter or when the box is left, not at
    // every keystroke (a frame count typed as 1, 10, 102 would clamp the
    // current frame at 1).
    for (QAbstractSpinBox* box : std::initializer_list<QAbstractSpinBox*>{degrees_, frames_, start_, fps_})
        box->setKeyboardTracking(false);
    // Two rows: the settings, then play and the scrubber across the whole
    // width (in one row, a file's camera and clip names left the scrubber a
    // few pixels at 1280 x 800).
    auto* rows = new QVBoxLayout(this);
    auto* settings = new QHBoxLayout;
    for (QWidget* w : std::initializer_list<QWidget*>{source_, camera_, degrees_, start_, frames_, fps_, loop_, everyFrame_})
        settings->addWidget(w);
    settings->addStretch(1);
    auto* scrub = new QHBoxLayout;
    scrub->addWidget(play_);
    scrub->addWidget(slider_, 1);
    scrub->addWidget(frameBox_);
    scrub->addWidget(label_);
    rows->addLayout(settings);
    rows->addLayout(scrub);
    slider_->setMinimumWidth(240);
    // Nothing moves sideways as play starts or stops: the button is as wide
    // as its wider text, the position as wide as its longest.
    play_->setMinimumWidth(std::max(play_->fontMetrics().horizontalAdvance(tr("Pause")),
                                    play_->fontMetrics().horizontalAdvance(tr("Play"))) + 32);
    label_->setMinimumWidth(label_->fontMetrics().horizontalAdvance(tr("/ 99999 · 9999.99 s of 9999.99 s · 240.0 fps shown")));
}

void Timeline::connectWidgets() {
    auto refresh = [this] {
        showPosition();
        emit changed();
    };
    connect(frameBox_, &QSpinBox::valueChanged, this, [this](int frame) { setFrame(frame); });
    connect(slider_, &QSlider::valueChanged, this, refresh);
    connect(source_, &QComboBox::currentIndexChanged, this, [this, refresh] {
        updateEnabled();
        // A clip plays its own length at the rate set, a sequence its files.
        const auto kind = AnimationSpec::Kind(source_->currentData(kKindRole).toInt());
        if (!quiet_ && (kind == AnimationSpec::Kind::Clip || kind == AnimationSpec::Kind::Camera)) {
            ++quiet_;
            setFrameCount(clip_frame_count(source_->currentData(kSecondsRole).toDouble(), fps_->value()));
            if (kind == AnimationSpec::Kind::Camera) // the moving camera is the one looked through
                camera_->setCurrentIndex(std::max(0, camera_->findData(source_->currentData(kCameraRole))));
            --quiet_;
        }
        if (!quiet_ && kind == AnimationSpec::Kind::Sequence && source_->currentData(kCountRole).toInt() > 0) {
            ++quiet_;
            setFrameCount(std::max(1, source_->currentData(kCountRole).toInt() - start_->value()));
            --quiet_;
        }
        refresh();
        edited();
    });
    connect(camera_, &QComboBox::currentIndexChanged, this, [this, refresh] {
        refresh();
        edited();
    });
    connect(degrees_, &QDoubleSpinBox::valueChanged, this, [this, refresh] {
        refresh();
        edited();
    });
    connect(start_, &QSpinBox::valueChanged, this, [this, refresh] {
        refresh();
        edited();
    });
    connect(fps_, &QDoubleSpinBox::valueChanged, this, [this, refresh] {
        anchorClock(); // on from here at the new rate
        refresh(); // a clip's frames are at other times now
        edited();
    });
    connect(frames_, &QSpinBox::valueChanged, this, [this](int n) {
        setFrameCount(n);
        emit changed();
        edited();
    });
    connect(play_, &QPushButton::clicked, this, &Timeline::togglePlay);
    connect(&timer_, &QTimer::timeout, this, &Timeline::advance);
    connect(everyFrame_, &QCheckBox::toggled, this, [this] {
        anchorClock();
        lastStepNs_ = 0;
    });
    // A frame the user picks while playing: play goes on from there.
    connect(slider_, &QSlider::valueChanged, this, [this] {
        if (playing() && !advancing_) anchorClock();
    });
}

void Timeline::setClips(const std::vector<AnimationClipInfo>& clips) {
    ++quiet_;
    AnimationSpec before;
    before.kind = AnimationSpec::Kind::Turntable; // the first time
    if (source_->count()) before = spec();
    source_->clear();
    source_->addItem(tr("Turntable"), int(AnimationSpec::Kind::Turntable));
    source_->addItem(tr("Orbiting light"), int(AnimationSpec::Kind::LightOrbit));
    source_->addItem(tr("Still"), int(AnimationSpec::Kind::Still));
    for (const AnimationClipInfo& clip : clips) {
        source_->addItem(tr("Clip: %1").arg(QString::fromStdString(clip.name)), int(AnimationSpec::Kind::Clip));
        source_->setItemData(source_->count() - 1, QString::fromStdString(clip.name), kClipRole);
        source_->setItemData(source_->count() - 1, clip.duration, kSecondsRole);
    }
    if (before.kind == AnimationSpec::Kind::LightOrbit || before.kind == AnimationSpec::Kind::Still)
        source_->setCurrentIndex(source_->findData(int(before.kind), kKindRole));
    updateEnabled();
    --quiet_;
}

void Timeline::setCameras(const std::vector<FileCamera>& cameras) {
    ++quiet_;
    // The sources of the last file's cameras go; this file's come.
    for (int i = source_->count() - 1; i >= 0; --i)
        if (AnimationSpec::Kind(source_->itemData(i, kKindRole).toInt()) == AnimationSpec::Kind::Camera) source_->removeItem(i);
    while (camera_->count() > 1) camera_->removeItem(1);
    camera_->setCurrentIndex(0);
    for (const FileCamera& c : cameras) {
        const QString name = QString::fromStdString(c.name);
        camera_->addItem(tr("Camera: %1").arg(name), name);
        if (!c.animated()) continue;
        source_->addItem(tr("Camera move: %1").arg(name), int(AnimationSpec::Kind::Camera));
        const int i = source_->count() - 1;
        source_->setItemData(i, QString::fromStdString(c.clip), kClipRole);
        source_->setItemData(i, c.clip_seconds, kSecondsRole);
        source_->setItemData(i, name, kCameraRole);
    }
    camera_->setVisible(!cameras.empty());
    updateEnabled();
    --quiet_;
}

bool Timeline::setSpec(const AnimationSpec& s) {
    ++quiet_;
    int index = 0; // the turntable, if the source cannot be shown
    bool found = true;
    switch (s.kind) {
    case AnimationSpec::Kind::Turntable:
    case AnimationSpec::Kind::LightOrbit:
    case AnimationSpec::Kind::Still: index = source_->findData(int(s.kind), kKindRole); break;
    case AnimationSpec::Kind::Camera: {
        found = false;
        for (int i = 0; i < source_->count() && !found; ++i)
            if (AnimationSpec::Kind(source_->itemData(i, kKindRole).toInt()) == AnimationSpec::Kind::Camera &&
                source_->itemData(i, kCameraRole).toString().toStdString() == s.camera)
                index = i, found = true;
        break;
    }
    case AnimationSpec::Kind::Clip: {
        found = false;
        int nth = 0;
        for (int i = 0; i < source_->count() && !found; ++i) {
            if (AnimationSpec::Kind(source_->itemData(i, kKindRole).toInt()) != AnimationSpec::Kind::Clip) continue;
            if (source_->itemData(i, kClipRole).toString().toStdString() == s.clip || (s.clip.empty() && nth == 0) ||
                std::to_string(nth) == s.clip)
                index = i, found = true;
            ++nth;
        }
        break;
    }
    case AnimationSpec::Kind::Sequence: {
        // One sequence at a time: the one shown replaces any other.
        const QString pattern = QString::fromStdString(s.pattern);
        const int old = source_->findData(int(AnimationSpec::Kind::Sequence), kKindRole);
        // The same sequence again (an undo step) keeps its file count.
        const int count = old >= 0 && source_->itemData(old, kPatternRole).toString() == pattern
                              ? source_->itemData(old, kCountRole).toInt()
                              : 0;
        if (old >= 0) source_->removeItem(old);
        source_->addItem(tr("Sequence: %1").arg(QFileInfo(pattern).fileName()), int(AnimationSpec::Kind::Sequence));
        index = source_->count() - 1;
        source_->setItemData(index, pattern, kPatternRole);
        source_->setItemData(index, s.first_file, kFirstRole);
        source_->setItemData(index, count, kCountRole);
        source_->setItemData(index, QDir::toNativeSeparators(pattern), Qt::ToolTipRole);
        break;
    }
    }
    source_->setCurrentIndex(std::max(index, 0));
    // The camera looked through: the file's, if it has that camera.
    const int camera = s.camera.empty() ? 0 : camera_->findData(QString::fromStdString(s.camera));
    if (camera < 0) found = false;
    camera_->setCurrentIndex(std::max(camera, 0));
    degrees_->setValue(s.degrees_per_frame);
    start_->setValue(s.start);
    fps_->setValue(s.fps);
    int frames = s.frames;
    if (frames <= 0 && (s.kind == AnimationSpec::Kind::Clip || s.kind == AnimationSpec::Kind::Camera) && found)
        frames = clip_frame_count(source_->itemData(index, kSecondsRole).toDouble(), s.fps);
    setFrameCount(std::max(frames, 1));
    updateEnabled();
    --quiet_;
    emit changed();
    return found;
}

void Timeline::applyPending() {
    for (QAbstractSpinBox* box : std::initializer_list<QAbstractSpinBox*>{degrees_, frames_, start_, fps_, frameBox_})
        box->interpretText(); // signals a value typed, as Enter would (a box showing its value signals nothing)
}

void Timeline::setSequenceFiles(int count) {
    const int index = source_->findData(int(AnimationSpec::Kind::Sequence), kKindRole);
    if (index >= 0) source_->setItemData(index, count, kCountRole);
}

void Timeline::edited() {
    if (!quiet_) emit specEdited();
}

void Timeline::updateEnabled() {
    const auto kind = AnimationSpec::Kind(source_->currentData(kKindRole).toInt());
    degrees_->setEnabled(kind == AnimationSpec::Kind::Turntable || kind == AnimationSpec::Kind::LightOrbit);
    camera_->setEnabled(kind != AnimationSpec::Kind::Camera); // the moving camera looks
}

AnimationSpec Timeline::spec() const {
    AnimationSpec s;
    s.kind = AnimationSpec::Kind(source_->currentData(kKindRole).toInt());
    if (s.kind == AnimationSpec::Kind::Clip || s.kind == AnimationSpec::Kind::Camera)
        s.clip = source_->currentData(kClipRole).toString().toStdString();
    s.camera = s.kind == AnimationSpec::Kind::Camera ? source_->currentData(kCameraRole).toString().toStdString()
                                                     : camera_->currentData().toString().toStdString();
    if (s.kind == AnimationSpec::Kind::Sequence) {
        s.pattern = source_->currentData(kPatternRole).toString().toStdString();
        s.first_file = source_->currentData(kFirstRole).toInt();
    }
    s.degrees_per_frame = degrees_->value();
    s.frames = frames_->value();
    s.start = start_->value();
    s.fps = fps_->value();
    return s;
}

int Timeline::frame() const { return slider_->value(); }
int Timeline::sourceFrame() const { return start_->value() + slider_->value(); }
void Timeline::setFrame(int frame) { slider_->setValue(std::clamp(frame, 0, frames_->value() - 1)); }

void Timeline::setFrameCount(int frames) {
    if (frames_->value() != frames) frames_->setValue(frames);
    slider_->setRange(0, frames - 1);
    showPosition();
}

void Timeline::showPosition() {
    const QSignalBlocker quiet(frameBox_);
    frameBox_->setRange(0, slider_->maximum());
    frameBox_->setValue(slider_->value());
    const double fps = fps_->value();
    QString text = tr("/ %1 · %2 s of %3 s")
                       .arg(slider_->maximum())
                       .arg(slider_->value() / fps, 0, 'f', 2)
                       .arg(frames_->value() / fps, 0, 'f', 2);
    if (playing()) text += tr(" · %1 fps shown").arg(shownRate_, 0, 'f', 1);
    label_->setText(text);
}

bool Timeline::playsEveryFrame() const { return everyFrame_->isChecked(); }

void Timeline::setPlaysEveryFrame(bool every) { everyFrame_->setChecked(every); }

void Timeline::togglePlay() {
    if (timer_.isActive()) {
        timer_.stop();
        shownAt_.clear();
        shownRate_ = 0.0;
        status_.clear();
        showPosition();
        emit playbackStatus({});
    } else {
        clock_.start();
        anchorClock();
        lastStepNs_ = rateAt_ = 0;
        lastShown_ = frame(); // on screen when play starts
        timer_.start();
    }
    play_->setChecked(timer_.isActive());
    play_->setText(timer_.isActive() ? tr("Pause") : tr("Play"));
}

void Timeline::anchorClock() {
    clockStartFrame_ = frame();
    clockStartNs_ = clock_.isValid() ? clock_.nsecsElapsed() : 0;
}

int Timeline::nextFrame(int frame) const {
    if (frame + 1 < frames_->value()) return frame + 1;
    return loop_->isChecked() ? 0 : -1;
}

void Timeline::frameShown(int frame) {
    if (!playing()) return;
    lastShown_ = frame;
    shownAt_.push_back(clock_.nsecsElapsed());
    updateRate();
}

void Timeline::updateRate() {
    const qint64 now = clock_.nsecsElapsed();
    rateAt_ = now;
    while (!shownAt_.empty() && shownAt_.front() < now - 1'000'000'000) shownAt_.pop_front();
    // Over the last second (or the time played, at the start).
    const double window = std::clamp(double(now) * 1e-9, 0.25, 1.0);
    shownRate_ = double(shownAt_.size()) / window;
    const double set = fps_->value();
    showPosition();
    if (now < 1'000'000'000) return; // too early to judge
    QString status;
    if (shownRate_ < 0.95 * set)
        status = everyFrame_->isChecked()
                     ? tr("Preview slower than real time: %1 of %2 fps, every frame shown").arg(shownRate_, 0, 'f', 1).arg(set)
                     : tr("Preview slower than real time: %1 of %2 fps, dropping frames to keep time")
                           .arg(shownRate_, 0, 'f', 1)
                           .arg(set);
    else
        status = tr("Preview at full rate (%1 fps)").arg(set);
    if (status != status_) emit playbackStatus(status_ = status);
}

void Timeline::step(int delta) {
    const int n = frames_->value();
    setFrame(((frame() + delta) % n + n) % n);
}

void Timeline::advance() {
    const qint64 now = clock_.nsecsElapsed();
    const double fps = fps_->value();
    const int n = frames_->value();
    // Nothing shown for a while: say so, four times a second (not every tick).
    if ((shownAt_.empty() || now - shownAt_.back() > 250'000'000) && now - rateAt_ > 250'000'000) updateRate();
    if (everyFrame_->isChecked()) {
        // The next frame once this one is shown, and no sooner than the rate allows.
        if (lastShown_ != frame() || now - lastStepNs_ < qint64(1e9 / fps)) return;
        const int next = nextFrame(frame());
        if (next < 0) return togglePlay();
        lastStepNs_ = now;
        advancing_ = true;
        setFrame(next);
        advancing_ = false;
        return;
    }
    // The frame due now by the clock; those the preview had no time for are dropped.
    const qint64 due = clockStartFrame_ + qint64(double(now - clockStartNs_) * 1e-9 * fps);
    advancing_ = true;
    if (due >= n && !loop_->isChecked()) {
        setFrame(n - 1);
        advancing_ = false;
        return togglePlay();
    }
    const int frame_due = int(due % n);
    if (frame_due != frame()) setFrame(frame_due);
    advancing_ = false;
}

} // namespace snaxels::ui
