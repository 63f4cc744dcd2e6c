#include "ui/timeline.h"

#include <cmath>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>

namespace snaxels::ui {
namespace {
constexpr int kKindRole = Qt::UserRole;
constexpr int kClipRole = Qt::UserRole + 1;
constexpr int kSecondsRole = Qt::UserRole + 2;
} // namespace

Timeline::Timeline(QWidget* parent)
    : QWidget(parent), source_(new QComboBox(this)), degrees_(new QDoubleSpinBox(this)), frames_(new QSpinBox(this)),
      start_(new QSpinBox(this)), fps_(new QDoubleSpinBox(this)), slider_(new QSlider(Qt::Horizontal, this)), label_(new QLabel(this)),
      play_(new QPushButton(tr("Play"), this)), loop_(new QCheckBox(tr("Loop"), this)) {
    setClips({});
    source_->setToolTip(tr("What moves from frame to frame"));
    degrees_->setRange(-90.0, 90.0);
    degrees_->setDecimals(2);
    degrees_->setValue(2.0);
    degrees_->setSuffix(tr("°/frame"));
    frames_->setRange(1, 100000);
    frames_->setValue(180);
    frames_->setSuffix(tr(" frames"));
    start_->setRange(0, 1000000);
    start_->setPrefix(tr("from "));
    start_->setToolTip(tr("In point: the source's frame the animation begins at"));
    fps_->setRange(1.0, 240.0);
    fps_->setValue(24.0);
    fps_->setSuffix(tr(" fps"));
    slider_->setRange(0, frames_->value() - 1);
    loop_->setChecked(true);
    play_->setCheckable(true);
    auto* layout = new QHBoxLayout(this);
    for (QWidget* w : std::initializer_list<QWidget*>{source_, degrees_, start_, frames_, fps_, play_, loop_}) layout->addWidget(w);
    layout->addWidget(slider_, 1);
    layout->addWidget(label_);
    auto refresh = [this] {
        label_->setText(tr("frame %1 / %2").arg(slider_->value()).arg(frames_->value() - 1));
        emit changed();
    };
    connect(slider_, &QSlider::valueChanged, this, refresh);
    connect(source_, &QComboBox::currentIndexChanged, this, [this, refresh] {
        updateEnabled();
        // A clip plays its own length at the rate set.
        if (!quiet_ && AnimationSpec::Kind(source_->currentData(kKindRole).toInt()) == AnimationSpec::Kind::Clip) {
            ++quiet_;
            setFrameCount(clip_frame_count(source_->currentData(kSecondsRole).toDouble(), fps_->value()));
            --quiet_;
        }
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
        timer_.setInterval(int(1000.0 / fps_->value()));
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
    timer_.setInterval(int(1000.0 / fps_->value()));
    label_->setText(tr("frame 0 / %1").arg(frames_->value() - 1));
}

void Timeline::setClips(const std::vector<AnimationClipInfo>& clips) {
    ++quiet_;
    const AnimationSpec before = source_->count() ? spec() : AnimationSpec{};
    source_->clear();
    source_->addItem(tr("Turntable"), int(AnimationSpec::Kind::Turntable));
    source_->addItem(tr("Orbiting light"), int(AnimationSpec::Kind::LightOrbit));
    for (const AnimationClipInfo& clip : clips) {
        source_->addItem(tr("Clip: %1").arg(QString::fromStdString(clip.name)), int(AnimationSpec::Kind::Clip));
        source_->setItemData(source_->count() - 1, QString::fromStdString(clip.name), kClipRole);
        source_->setItemData(source_->count() - 1, clip.duration, kSecondsRole);
    }
    if (before.kind == AnimationSpec::Kind::LightOrbit) source_->setCurrentIndex(1);
    updateEnabled();
    --quiet_;
}

bool Timeline::setSpec(const AnimationSpec& s) {
    ++quiet_;
    int index = s.kind == AnimationSpec::Kind::LightOrbit ? 1 : 0;
    bool found = s.kind == AnimationSpec::Kind::Turntable || s.kind == AnimationSpec::Kind::LightOrbit;
    if (s.kind == AnimationSpec::Kind::Clip)
        for (int i = 2; i < source_->count(); ++i)
            if (source_->itemData(i, kClipRole).toString().toStdString() == s.clip ||
                (s.clip.empty() && i == 2) || std::to_string(i - 2) == s.clip) {
                index = i;
                found = true;
                break;
            }
    source_->setCurrentIndex(index);
    degrees_->setValue(s.degrees_per_frame);
    start_->setValue(s.start);
    fps_->setValue(s.fps);
    int frames = s.frames;
    if (frames <= 0 && index >= 2)
        frames = clip_frame_count(source_->itemData(index, kSecondsRole).toDouble(), s.fps);
    setFrameCount(std::max(frames, 1));
    updateEnabled();
    --quiet_;
    emit changed();
    return found;
}

void Timeline::edited() {
    if (!quiet_) emit specEdited();
}

void Timeline::updateEnabled() {
    const auto kind = AnimationSpec::Kind(source_->currentData(kKindRole).toInt());
    degrees_->setEnabled(kind != AnimationSpec::Kind::Clip);
}

AnimationSpec Timeline::spec() const {
    AnimationSpec s;
    s.kind = AnimationSpec::Kind(source_->currentData(kKindRole).toInt());
    if (s.kind == AnimationSpec::Kind::Clip) s.clip = source_->currentData(kClipRole).toString().toStdString();
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
    label_->setText(tr("frame %1 / %2").arg(slider_->value()).arg(frames - 1));
}

void Timeline::togglePlay() {
    if (timer_.isActive()) timer_.stop();
    else timer_.start();
    play_->setChecked(timer_.isActive());
    play_->setText(timer_.isActive() ? tr("Pause") : tr("Play"));
}

void Timeline::step(int delta) {
    const int n = frames_->value();
    setFrame(((frame() + delta) % n + n) % n);
}

void Timeline::advance() {
    if (frame() + 1 < frames_->value()) setFrame(frame() + 1);
    else if (loop_->isChecked()) setFrame(0);
    else togglePlay();
}

} // namespace snaxels::ui
