// A seeded robot that uses the real window as a user might: orbit, zoom and
// light drags, presets and broken styles typed in, timeline scrubs and
// play, undo and redo bursts, meshes opened from a pool that includes bad
// files, frames exported, animation exports started and cancelled, and the
// window closed at the end with work under way, projects saved and opened.
// After every action it checks what must always hold (among it, that the
// undo stack carried out on a fresh document gives the document's state);
// at checkpoints it waits for the window to settle and checks that the SVG
// pane shows what snaxels-cli renders for the same project. Every 250
// actions it returns to a baseline (the first mesh open, nothing running)
// and samples the resident memory there; --max-rss-growth fails the run
// when the last baseline exceeds the first after the warm-up (the first
// tenth of them) by more than FRACTION. Every action is logged so that a
// failure replays from its log.
//
//   snaxels-robot [--seconds S] [--seed N] [--log FILE] [--replay FILE]
//                 [--max-rss-growth FRACTION]
//
// Each log line is "ACTION A B" (two integers). --replay performs exactly
// the actions of a log, in order; without it the actions are drawn from the
// seed until the time is up. Exit 0 when every check held, 1 when one did
// not (the message names the step), 2 on a bad command line.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QProcess>
#include <QRegularExpression>
#include <QProgressDialog>
#include <QPushButton>
#include <QSet>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUndoStack>
#include <QWheelEvent>
#include <QXmlStreamReader>

#include "snaxels/style/style.h"
#include "ui/document.h"
#include "ui/mainwindow.h"
#include "ui/meshview.h"
#include "ui/resources.h"
#include "ui/styleeditor.h"
#include "ui/timeline.h"
#include "ui/undo.h"

using snaxels::ui::Document;
using snaxels::ui::MainWindow;
using snaxels::ui::MeshView;

namespace {

enum class Act {
    Orbit, Zoom, Light, Preset, BrokenStyle, Scrub, Play, Undo, Redo, Open, ExportFrame, ExportAnimation, Wait,
    Save, Checkpoint, Baseline, Count
};
const char* kNames[] = {"orbit", "zoom", "light", "preset", "broken-style", "scrub", "play", "undo", "redo",
                        "open", "export-frame", "export-animation", "wait", "save", "checkpoint", "baseline"};
// How often each is drawn.
// How often each is drawn (a baseline is never drawn: the robot takes one
// every kBaselineEvery actions).
const int kWeights[] = {20, 10, 8, 6, 3, 8, 3, 6, 4, 3, 3, 2, 10, 2, 2, 0};
constexpr std::size_t kBaselineEvery = 250;

struct Action {
    Act act;
    int a = 0, b = 0;
    std::string text() const { return std::string(kNames[int(act)]) + " " + std::to_string(a) + " " + std::to_string(b); }
};

bool parse_action(const std::string& line, Action& out) {
    std::istringstream in(line);
    std::string name;
    if (!(in >> name >> out.a >> out.b)) return false;
    for (int i = 0; i < int(Act::Count); ++i)
        if (name == kNames[i]) {
            out.act = Act(i);
            return true;
        }
    return false;
}

Action draw(std::mt19937& rng) {
    int total = 0;
    for (const int w : kWeights) total += w;
    int pick = std::uniform_int_distribution<int>(0, total - 1)(rng);
    int i = 0;
    while (pick >= kWeights[i]) pick -= kWeights[i++];
    std::uniform_int_distribution<int> any(-1000, 1000);
    return {Act(i), any(rng), any(rng)};
}

long rss_kb() {
    std::ifstream statm("/proc/self/statm");
    long pages = 0, resident = 0;
    statm >> pages >> resident;
    return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

/// Answers every message box while it lives (the unsaved-changes question
/// with Discard, any other with its default button), counting them.
struct AnswerMessageBoxes {
    AnswerMessageBoxes() {
        poll.setInterval(15);
        QObject::connect(&poll, &QTimer::timeout, [this] {
            auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            if (!box) return;
            ++answered;
            if (QAbstractButton* discard = box->button(QMessageBox::Discard)) discard->click();
            else if (QAbstractButton* ok = box->defaultButton()) ok->click();
            else box->reject();
        });
        poll.start();
    }
    QTimer poll;
    int answered = 0;
};

/// Empty when @p svg is well-formed XML, else what is wrong and where.
QString xml_error(const QByteArray& svg) {
    QXmlStreamReader xml(svg);
    while (!xml.atEnd()) xml.readNext();
    if (!xml.hasError()) return {};
    return QString("%1 at line %2, column %3 (%4 bytes)").arg(xml.errorString()).arg(xml.lineNumber()).arg(xml.columnNumber()).arg(svg.size());
}
bool parses(const QByteArray& svg) { return xml_error(svg).isEmpty(); }

class Robot {
  public:
    Robot(MainWindow& window, const QString& work) : window_(window), work_(work) {
        const QString assets = SNAXELS_TEST_ASSETS;
        pool_ = {assets + "/spot.obj", assets + "/horse.ply", assets + "/teapot.obj", "proc:nose:20000",
                 assets + "/anim/morph-ball.gltf", assets + "/hard/CesiumMilkTruck.gltf"};
        for (const QString& bad : QDir(assets + "/bad").entryList(QDir::Files)) pool_.push_back(assets + "/bad/" + bad);
        // Projects of every version, and one from a newer version (refused).
        const QString compat = assets + "/projects/compat";
        for (const QString& version : QDir(compat).entryList(QDir::Dirs | QDir::NoDotAndDotDot))
            for (const QString& project : QDir(compat + "/" + version).entryList({"*.snaxels"}, QDir::Files))
                pool_.push_back(compat + "/" + version + "/" + project);
        for (const char* name : {"toon", "shading-lines", "pencil-sketch", "ink-outline", "technical-drawing", "clip-art"}) {
            QFile f(snaxels::ui::dataDirectory() + "/styles/" + name + ".xml");
            if (f.open(QIODevice::ReadOnly)) presets_.push_back(QString::fromUtf8(f.readAll()));
        }
    }

    /// Performs @p a; false (with @p why) when a check fails after it.
    bool perform(const Action& a, QString& why) {
        MeshView* view = window_.meshView();
        const QPoint centre = view->rect().center();
        switch (a.act) {
        case Act::Orbit:
        case Act::Light: {
            const Qt::KeyboardModifiers mods = a.act == Act::Light ? Qt::ShiftModifier : Qt::NoModifier;
            const QPoint to = centre + QPoint(a.a / 5, a.b / 5);
            QTest::mousePress(view, Qt::LeftButton, mods, centre);
            QTest::mouseMove(view, (centre + to) / 2);
            QTest::mouseMove(view, to);
            QTest::mouseRelease(view, Qt::LeftButton, mods, to);
            break;
        }
        case Act::Zoom: {
            QWheelEvent wheel(centre, view->mapToGlobal(centre), QPoint(), QPoint(0, a.a > 0 ? 120 : -120), Qt::NoButton,
                              Qt::NoModifier, Qt::NoScrollPhase, false);
            QApplication::sendEvent(view, &wheel);
            break;
        }
        case Act::Preset:
            if (!presets_.empty()) window_.styleEditor()->editor()->setPlainText(presets_[std::size_t(std::abs(a.a)) % presets_.size()]);
            break;
        case Act::BrokenStyle: {
            const QStringList broken{"<style><contour kind=\"visual\"", "<style><contour kind=\"banana\"/></style>",
                                     "<style><canvas width=\"-3\"/></style>", "not xml at all", ""};
            window_.styleEditor()->editor()->setPlainText(broken[std::abs(a.a) % broken.size()]);
            break;
        }
        case Act::Scrub:
            window_.timeline()->setFrame(std::abs(a.a) % 200);
            break;
        case Act::Play:
            QTest::keyClick(&window_, Qt::Key_Space);
            break;
        case Act::Undo:
        case Act::Redo: // the Edit menu's actions, as Ctrl+Z outside the editor triggers them
            for (int i = 0; i < 1 + std::abs(a.a) % 5; ++i) action(a.act == Act::Undo ? QKeySequence::Undo : QKeySequence::Redo)->trigger();
            break;
        case Act::Open:
            // Now and then a project this run saved, else one of the pool.
            if (!saved_.empty() && a.b % 3 == 0) window_.openFile(saved_[std::size_t(std::abs(a.a)) % saved_.size()]);
            else window_.openFile(pool_[std::size_t(std::abs(a.a)) % pool_.size()]);
            break;
        case Act::Save: {
            const QString path = work_ + QString("/project-%1.snaxels").arg(++exports_);
            asked_.insert(QFileInfo(path).fileName());
            if (window_.saveProject(path)) saved_.push_back(path);
            break;
        }
        case Act::Checkpoint:
            if (!matchesCli(why)) return false;
            break;
        case Act::Baseline:
            // The same state each time (the first mesh of the pool, open
            // and drawn, nothing running): the memory it takes is comparable
            // over the run, whatever the actions between left loaded.
            window_.openFile(pool_.front());
            settle();
            QTest::qWait(1500); // the window returns freed memory a second after it settles
            baselines_.push_back(rss_kb());
            break;
        case Act::ExportFrame: {
            const QString path = work_ + QString("/frame-%1.svg").arg(++exports_);
            asked_.insert(QFileInfo(path).fileName());
            if (window_.exportFrame(path) && !parses(read(path))) return fail(why, path + " is not a whole SVG: " + xml_error(read(path)));
            break;
        }
        case Act::ExportAnimation: {
            const QString path = work_ + QString("/anim-%1.svg").arg(++exports_);
            asked_.insert(QFileInfo(path).fileName());
            window_.exportAnimation(path);
            QTest::qWait(std::abs(a.b) % 300);
            for (QWidget* w : QApplication::topLevelWidgets())
                if (auto* progress = qobject_cast<QProgressDialog*>(w); progress && progress->isVisible() && a.a % 2 == 0)
                    progress->cancel();
            break;
        }
        case Act::Wait:
            QTest::qWait(std::abs(a.a) % 400);
            break;
        case Act::Count:
            break;
        }
        QApplication::processEvents();
        return check(why);
    }

    /// What always holds.
    bool check(QString& why) {
        if (!window_.isVisible()) return fail(why, "the window is gone");
        QUndoStack* undo = window_.undoStack();
        if (undo->index() < 0 || undo->index() > undo->count()) return fail(why, "the undo stack's index is out of range");
        if (!window_.isLoading() && !window_.contoursBusy() && !window_.currentSvg().isEmpty() && !parses(window_.currentSvg()))
            return fail(why, "the SVG pane holds a broken SVG");
        const Document& document = *window_.document();
        if (!window_.styleEditor()->pending() && window_.styleEditor()->text() != document.styleText())
            return fail(why, "the style editor shows another text than the document has (and no typing waits to be applied)");
        if (!replayMatches(why)) return false;
        // Only files the robot asked for, and no temporary ones once no export runs.
        for (const QString& name : QDir(work_).entryList(QDir::Files))
            if (!asked_.contains(name) && !exporting()) return fail(why, "a file nobody asked for: " + name);
        return true;
    }

    /// Every export asked for is whole, or absent (cancelled, or failed).
    bool finalCheck(QString& why) {
        for (const QString& name : QDir(work_).entryList(QDir::Files)) {
            if (!asked_.contains(name)) return fail(why, "a file nobody asked for: " + name);
            const QByteArray bytes = read(work_ + "/" + name);
            if (name.endsWith(".snaxels")) {
                QJsonParseError error;
                if (QJsonDocument::fromJson(bytes, &error).isNull()) return fail(why, name + " is not a whole project: " + error.errorString());
            } else if (!parses(bytes)) {
                return fail(why, name + " is not a whole SVG");
            }
        }
        return true;
    }

    bool exporting() const {
        if (window_.exporting()) return true;
        for (QWidget* w : QApplication::topLevelWidgets())
            if (qobject_cast<QProgressDialog*>(w) && w->isVisible()) return true;
        return false;
    }

    /// The undo stack's steps up to its index, carried out on a fresh
    /// document from where the history begins, give the document's state.
    /// The camera is left out under a turntable: there the frame turns it,
    /// which is not an edit (scrubbing is not undone).
    bool replayMatches(QString& why) const {
        const Document& live = *window_.document();
        Document fresh(QString{});
        fresh.restore(live.historyStart());
        const QUndoStack* stack = live.undoStack();
        for (int i = 0; i < stack->index(); ++i) {
            const auto* step = dynamic_cast<const snaxels::ui::DocumentStep*>(stack->command(i));
            if (!step) return fail(why, QString("undo step %1 (%2) is not a document step").arg(i).arg(stack->command(i)->text()));
            step->applyTo(fresh);
        }
        Document::Edited want = fresh.edited(), have = live.edited();
        if (have.animation.kind == snaxels::AnimationSpec::Kind::Turntable) want.view = have.view;
        if (want == have) return true;
        const QString part = want.style != have.style         ? "style"
                             : want.view != have.view         ? "camera"
                             : want.light != have.light       ? "light"
                                                              : "animation";
        return fail(why, QString("replaying the %1 undo steps below the index (of %2) on a fresh document gives another %3")
                             .arg(stack->index()).arg(stack->count()).arg(part));
    }

    /// Once the window has settled, the SVG pane holds what snaxels-cli
    /// renders as a still for the document saved as a project.
    /// Stops playback and waits (a minute at most) until nothing runs.
    void settle() {
        if (window_.timeline()->playing()) QTest::keyClick(&window_, Qt::Key_Space);
        // Space goes to a text box that has the focus: then Play > Play / Pause.
        if (window_.timeline()->playing())
            for (QAction* a : window_.findChildren<QAction*>())
                if (a->shortcut() == QKeySequence(Qt::Key_Space)) a->trigger();
        for (int i = 0; i < 2400 && (window_.isLoading() || window_.contoursBusy() || window_.parabolicPending() || exporting()); ++i)
            QTest::qWait(25);
    }

    /// The resident memory at each baseline.
    const std::vector<long>& baselines() const { return baselines_; }

    bool matchesCli(QString& why) {
        settle();
        if (window_.timeline()->playing()) return fail(why, "Play / Pause did not stop playback");
        if (window_.isLoading() || window_.contoursBusy() || exporting()) return true; // not settled: no checkpoint
        const Document& document = *window_.document();
        if (!document.mesh() || (window_.currentSvg().isEmpty() && window_.frameProblem().isEmpty())) return true;
        // Saved as the user saves it: what the widgets hold goes into the document first.
        const QString project = checkpoints_.filePath(QString("checkpoint-%1.snaxels").arg(++checkpointCount_));
        const QString svg = checkpoints_.filePath(QString("checkpoint-%1.svg").arg(checkpointCount_));
        if (!window_.saveProject(project)) return fail(why, "the project could not be saved to " + project);
        for (int i = 0; i < 2400 && (window_.contoursBusy() || window_.parabolicPending()); ++i) QTest::qWait(25);
        // While the text does not parse the pane shows the last style that
        // did, and the project holds the text (an empty one reads back as
        // the default style): no checkpoint.
        bool parses = !document.styleText().trimmed().isEmpty();
        try {
            if (parses) snaxels::parse_style(document.styleText().toStdString(), "style", nullptr);
        } catch (const std::exception&) {
            parses = false;
        }
        if (!parses) return QFile::remove(project);
        QProcess cli;
        cli.start(QCoreApplication::applicationDirPath() + "/snaxels-cli", {"render", project, "--still", "-o", svg});
        if (!cli.waitForFinished(600000)) return fail(why, "snaxels-cli render " + project + " did not end");
        // A frame that cannot be drawn: the CLI refuses it too, for the reason the pane gives.
        const QString cliError = QString::fromUtf8(cli.readAllStandardError()).trimmed().remove(QRegularExpression("^snaxels-cli: "));
        if (cli.exitCode() != 0 && (cliError.isEmpty() || !window_.frameProblem().endsWith(cliError)))
            return fail(why, "snaxels-cli render " + project + " failed (" + cliError + ") where the pane says: " +
                                 (window_.frameProblem().isEmpty() ? QString("nothing (it drew the frame)") : window_.frameProblem()));
        if (cli.exitCode() == 0 && !window_.frameProblem().isEmpty())
            return fail(why, "the pane says " + window_.frameProblem() + " where snaxels-cli render " + project + " draws it");
        const QByteArray shown = window_.currentSvg(), rendered = read(svg);
        if (shown != rendered) {
            QFile keep(svg + ".pane.svg");
            if (keep.open(QIODevice::WriteOnly)) keep.write(shown);
            checkpoints_.setAutoRemove(false);
            return fail(why, QString("the SVG pane (%1 bytes) differs from snaxels-cli render --still (%2 bytes); both are kept "
                                     "in %3 (timeline at frame %4, %5)")
                                 .arg(shown.size()).arg(rendered.size()).arg(checkpoints_.path())
                                 .arg(window_.timeline()->frame())
                                 .arg(window_.timeline()->playing() ? "still playing" : "not playing"));
        }
        QFile::remove(project);
        QFile::remove(svg);
        return true;
    }

    int checkpoints() const { return checkpointCount_; }

    /// The window's action with the shortcut @p key.
    QAction* action(QKeySequence::StandardKey key) const {
        for (QAction* a : window_.findChildren<QAction*>())
            if (a->shortcut() == QKeySequence(key)) return a;
        std::fprintf(stderr, "snaxels-robot: the window has no action for %s\n", qPrintable(QKeySequence(key).toString()));
        std::exit(1);
    }

  private:
    static bool fail(QString& why, const QString& text) {
        why = text;
        return false;
    }
    static QByteArray read(const QString& path) {
        QFile f(path);
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    }

    MainWindow& window_;
    QString work_;
    std::vector<QString> pool_;
    std::vector<QString> presets_;
    std::vector<QString> saved_;
    QSet<QString> asked_;
    QTemporaryDir checkpoints_;
    int checkpointCount_ = 0;
    std::vector<long> baselines_;
    int exports_ = 0;
};

} // namespace

int main(int argc, char** argv) {
    QSurfaceFormat format = QSurfaceFormat::defaultFormat();
    format.setDepthBufferSize(24);
    QSurfaceFormat::setDefaultFormat(format);
    std::setvbuf(stdout, nullptr, _IOLBF, 0); // each line out at once: a sanitizer ends the process without flushing
    QApplication app(argc, argv);
    QStandardPaths::setTestModeEnabled(true); // the user's settings and recent files stay untouched
    double seconds = 60.0, max_growth = -1.0;
    unsigned seed = 1;
    QString log_path, replay_path;
    const QStringList args = app.arguments();
    for (int i = 1; i < args.size(); ++i) {
        const QString& arg = args[i];
        const bool has_value = i + 1 < args.size();
        bool ok = true;
        if (arg == "--seconds" && has_value) {
            seconds = args[++i].toDouble(&ok);
            ok = ok && seconds > 0.0;
        } else if (arg == "--seed" && has_value) {
            seed = args[++i].toUInt(&ok);
        } else if (arg == "--log" && has_value) {
            log_path = args[++i];
        } else if (arg == "--replay" && has_value) {
            replay_path = args[++i];
        } else if (arg == "--max-rss-growth" && has_value) {
            max_growth = args[++i].toDouble(&ok);
            ok = ok && max_growth >= 0.0;
        } else {
            std::fprintf(stderr, "snaxels-robot: unknown argument %s\n", qPrintable(arg));
            return 2;
        }
        if (!ok) {
            std::fprintf(stderr, "snaxels-robot: %s needs a number (seconds above 0, a seed, a growth of 0 or more), not %s\n",
                         qPrintable(arg), qPrintable(args[i]));
            return 2;
        }
    }
    std::vector<Action> replay;
    if (!replay_path.isEmpty()) {
        std::ifstream in(replay_path.toStdString());
        if (!in) {
            std::fprintf(stderr, "snaxels-robot: cannot read %s\n", qPrintable(replay_path));
            return 2;
        }
        for (std::string line; std::getline(in, line);) {
            Action a{Act::Wait};
            if (!line.empty() && line[0] != '#' && !parse_action(line, a)) {
                std::fprintf(stderr, "snaxels-robot: %s: not an action: %s\n", qPrintable(replay_path), line.c_str());
                return 2;
            }
            if (!line.empty() && line[0] != '#') replay.push_back(a);
        }
    }
    std::ofstream log;
    if (!log_path.isEmpty()) log.open(log_path.toStdString());

    QTemporaryDir work;
    MainWindow window;
    window.resize(1100, 750);
    window.show();
    if (!QTest::qWaitForWindowExposed(&window)) {
        std::fprintf(stderr, "snaxels-robot: the window did not show\n");
        return 1;
    }
    AnswerMessageBoxes boxes;
    Robot robot(window, work.path());
    std::mt19937 rng(seed);
    QElapsedTimer clock;
    clock.start();
    std::size_t step = 0;
    std::printf("snaxels-robot: seed %u, %s\n", seed,
                replay.empty() ? qPrintable(QString("%1 s").arg(seconds)) : qPrintable(QString("replaying %1 actions").arg(replay.size())));
    int counts[int(Act::Count)] = {};
    while (replay.empty() ? clock.elapsed() < seconds * 1000.0 : step < replay.size()) {
        const Action a = !replay.empty()                        ? replay[step]
                         : step % kBaselineEvery == kBaselineEvery - 1 ? Action{Act::Baseline}
                                                                       : draw(rng);
        if (log.is_open()) log << a.text() << '\n' << std::flush; // written before it runs: a crash keeps it
        ++counts[int(a.act)];
        QString why;
        if (!robot.perform(a, why)) {
            std::printf("snaxels-robot: step %zu (%s): %s\n", step, a.text().c_str(), qPrintable(why));
            return 1;
        }
        ++step;
    }
    // Let what runs finish, then check the files, then close with work under way.
    for (int i = 0; i < 600 && (window.isLoading() || window.contoursBusy() || robot.exporting()); ++i) QTest::qWait(50);
    QString why;
    if (!robot.finalCheck(why)) {
        std::printf("snaxels-robot: at the end: %s\n", qPrintable(why));
        return 1;
    }
    std::string summary;
    for (int i = 0; i < int(Act::Count); ++i) summary += std::string(i ? ", " : "") + kNames[i] + " " + std::to_string(counts[i]);
    // Memory: the baselines after the first tenth of them (the warm-up:
    // caches filling, the allocator finding its size), the last against
    // the first of those.
    const std::vector<long>& rss = robot.baselines();
    const std::size_t warm = rss.size() / 10;
    const long after_warmup = rss.empty() ? 0 : rss[warm], last = rss.empty() ? 0 : rss.back();
    const long most = rss.empty() ? 0 : *std::max_element(rss.begin() + long(warm), rss.end());
    const double growth = after_warmup > 0 ? double(last - after_warmup) / double(after_warmup) : 0.0;
    std::printf("snaxels-robot: %zu actions (%s); %d checkpoints matched snaxels-cli; %d message boxes answered; %d undo "
                "steps at the end; RSS at %zu baselines: %ld KB after warm-up, at most %ld KB after, %ld KB at the end "
                "(%+.1f%%)\n",
                step, summary.c_str(), robot.checkpoints(), boxes.answered, window.undoStack()->count(), rss.size(),
                after_warmup, most, last, 100.0 * growth);
    if (max_growth >= 0.0 && rss.size() < 2) {
        std::printf("snaxels-robot: too few baselines (%zu) to judge the memory: run longer\n", rss.size());
        return 1;
    }
    if (max_growth >= 0.0 && growth > max_growth) {
        std::printf("snaxels-robot: RSS grew %.1f%%, more than %.1f%%\n", 100.0 * growth, 100.0 * max_growth);
        return 1;
    }
    window.openMesh(SNAXELS_TEST_ASSETS "/horse.ply"); // work under way as it closes
    window.close();
    return 0;
}
