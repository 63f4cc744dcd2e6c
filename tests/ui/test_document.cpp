// The application's document without a window or OpenGL: edits as undo
// steps, undo and redo restoring exact values and telling observers, the
// modified state, and project files written and read back. Expected values
// are spelled out here, not computed by the code under test.
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

#include <QFile>
#include <QFileInfo>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include "snaxels/animation/pipeline.h"
#include "snaxels/error.h"
#include "snaxels/project/project.h"
#include "ui/contour_scheduler.h"
#include "ui/document.h"
#include "ui/export_actions.h"
#include "ui/undo.h"

using snaxels::AnimationSpec;
using snaxels::Light;
using snaxels::OrbitView;
using snaxels::Project;
using snaxels::ui::Document;

namespace {

OrbitView view(double yaw, double pitch, double distance) {
    OrbitView v;
    v.yaw = yaw;
    v.pitch = pitch;
    v.distance = distance;
    return v;
}

Light directional(double x, double y, double z) {
    Light l;
    l.dir = {x, y, z};
    return l;
}

/// Edits of one kind within 1.5 s merge into one step: waiting apart keeps
/// them apart.
void pastMergeWindow() { QTest::qWait(1600); }

} // namespace

class TestDocument : public QObject {
    Q_OBJECT
  private slots:
    void startsCleanWithItsStyle() {
        Document doc("<style/>");
        QCOMPARE(doc.styleText(), QString("<style/>"));
        QVERIFY(!doc.isModified());
        QCOMPARE(doc.undoStack()->count(), 0);
        QVERIFY(doc.projectPath().isEmpty());
        QVERIFY(!doc.light().has_value());
    }

    void everyKindOfEditIsOneUndoStep() {
        Document doc("<style/>");
        QSignalSpy style(&doc, &Document::styleTextChanged);
        QSignalSpy camera(&doc, &Document::viewChanged);
        QSignalSpy light(&doc, &Document::lightChanged);
        QSignalSpy animation(&doc, &Document::animationChanged);
        QSignalSpy modified(&doc, &Document::modifiedChanged);

        doc.setStyleText("<style><canvas width=\"400\"/></style>");
        doc.setView(view(1.0, 0.5, 4.0));
        doc.setLight(directional(0.0, 1.0, 0.0));
        AnimationSpec turntable;
        turntable.kind = AnimationSpec::Kind::Turntable;
        turntable.degrees_per_frame = 3.0;
        turntable.frames = 120;
        doc.setAnimation(turntable);
        QCOMPARE(doc.undoStack()->count(), 4);
        QCOMPARE(style.count(), 1);
        QCOMPARE(camera.count(), 1);
        QCOMPARE(light.count(), 1);
        QCOMPARE(animation.count(), 1);
        QVERIFY(doc.isModified());
        QCOMPARE(modified.count(), 1);
        QCOMPARE(modified.last().at(0).toBool(), true);

        // Setting what is already there is no edit.
        doc.setView(view(1.0, 0.5, 4.0));
        doc.setStyleText("<style><canvas width=\"400\"/></style>");
        QCOMPARE(doc.undoStack()->count(), 4);
        QCOMPARE(camera.count(), 1);

        // Undo walks back through every kind, each observer told the old value.
        doc.undoStack()->undo();
        QCOMPARE(doc.animation(), AnimationSpec{});
        QCOMPARE(animation.count(), 2);
        QCOMPARE(animation.last().at(0).value<AnimationSpec>(), AnimationSpec{});
        doc.undoStack()->undo();
        QVERIFY(!doc.light().has_value());
        QCOMPARE(light.count(), 2);
        doc.undoStack()->undo();
        QCOMPARE(doc.view(), OrbitView{});
        QCOMPARE(camera.last().at(0).value<OrbitView>(), OrbitView{});
        doc.undoStack()->undo();
        QCOMPARE(doc.styleText(), QString("<style/>"));
        QCOMPARE(style.last().at(0).toString(), QString("<style/>"));
        QVERIFY(!doc.isModified()); // back where it started: clean
        QCOMPARE(modified.last().at(0).toBool(), false);

        // Redo replays them, exactly.
        for (int i = 0; i < 4; ++i) doc.undoStack()->redo();
        QCOMPARE(doc.styleText(), QString("<style><canvas width=\"400\"/></style>"));
        QCOMPARE(doc.view(), view(1.0, 0.5, 4.0));
        QCOMPARE(*doc.light(), directional(0.0, 1.0, 0.0));
        QCOMPARE(doc.animation().kind, AnimationSpec::Kind::Turntable);
        QCOMPARE(doc.animation().degrees_per_frame, 3.0);
        QCOMPARE(doc.animation().frames, 120);
        QVERIFY(doc.isModified());
    }

    void quickEditsOfOneKindMerge() {
        Document doc("<style/>");
        doc.setView(view(1.0, 0.3, 3.0)); // a drag or wheel turns: many edits in a row
        doc.setView(view(1.1, 0.3, 3.0));
        doc.setView(view(1.2, 0.3, 3.0));
        QCOMPARE(doc.undoStack()->count(), 1);
        pastMergeWindow();
        doc.setView(view(2.0, 0.3, 3.0));
        QCOMPARE(doc.undoStack()->count(), 2);
        doc.undoStack()->undo();
        QCOMPARE(doc.view(), view(1.2, 0.3, 3.0));
        doc.undoStack()->undo();
        QCOMPARE(doc.view(), OrbitView{});
        // Edits that return to the start within the window leave no step.
        Document back("<style/>");
        back.setLight(directional(1.0, 0.0, 0.0));
        back.setLight(std::nullopt);
        QCOMPARE(back.undoStack()->count(), 0);
        QVERIFY(!back.isModified());
    }

    void changesThatAreNotEditsLeaveNoStep() {
        Document doc("<style/>");
        QSignalSpy camera(&doc, &Document::viewChanged);
        doc.resetView(view(0.5, 0.2, 9.0)); // framing a new mesh
        AnimationSpec clip;
        clip.kind = AnimationSpec::Kind::Clip;
        clip.clip = "Walk";
        clip.frames = 48;
        doc.resetAnimation(clip);
        doc.setFrame(17);
        QCOMPARE(doc.undoStack()->count(), 0);
        QCOMPARE(camera.count(), 1);
        QCOMPARE(doc.view(), view(0.5, 0.2, 9.0));
        QCOMPARE(doc.frame(), 17);
        QVERIFY(!doc.isModified());
        // A new mesh is unsaved work, though no step undoes it.
        QSignalSpy mesh(&doc, &Document::meshChanged);
        doc.setMesh("proc:torus", nullptr);
        QCOMPARE(mesh.count(), 1);
        QCOMPARE(doc.meshSpec(), QString("proc:torus"));
        QVERIFY(doc.isModified());
        QCOMPARE(doc.undoStack()->count(), 0);
    }

    void savesAndReadsBackTheSameProject() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath("scene.snaxels");
        const QString sequence = dir.filePath("frames/pose_####.obj");
        Document doc("<style/>");
        doc.setMesh(dir.filePath("meshes/spot.obj"), nullptr);
        doc.setStyleText("<style><contour kind=\"visual\"/></style>");
        doc.setView(view(0.25, -0.125, 2.5));
        doc.setLight(directional(0.5, 0.75, -1.0));
        AnimationSpec seq;
        seq.kind = AnimationSpec::Kind::Sequence;
        seq.pattern = sequence.toStdString();
        seq.first_file = 1;
        seq.frames = 30;
        seq.fps = 12.0;
        doc.setAnimation(seq);
        doc.setFrame(7);
        QSignalSpy pathSpy(&doc, &Document::projectPathChanged);
        doc.save(path);
        QCOMPARE(pathSpy.count(), 1);
        QCOMPARE(doc.projectPath(), path);
        QVERIFY(!doc.isModified());
        QCOMPARE(doc.undoStack()->count(), 4); // the four edits (a mesh and a frame are none); saving keeps them

        // The file holds the document, paths relative to the project.
        const Project read = snaxels::read_project(path.toStdString());
        QCOMPARE(QString::fromStdString(read.mesh), QString("meshes/spot.obj"));
        QCOMPARE(QString::fromStdString(read.animation.pattern), QString("frames/pose_####.obj"));
        QCOMPARE(QString::fromStdString(read.style), QString("<style><contour kind=\"visual\"/></style>"));
        QCOMPARE(read.frame, 7);
        QCOMPARE(read.view, view(0.25, -0.125, 2.5));
        QCOMPARE(*read.light, directional(0.5, 0.75, -1.0));
        QCOMPARE(read.animation.frames, 30);
        QCOMPARE(read.animation.fps, 12.0);

        // Read into another document: the same values, clean, no history.
        Document again("<default/>");
        again.setStyleText("<edited/>"); // history that the opened project replaces
        QSignalSpy style(&again, &Document::styleTextChanged);
        again.load(read, path, QString::fromStdString(snaxels::resolve_project_mesh(path.toStdString(), read.mesh)),
                   nullptr);
        QCOMPARE(again.undoStack()->count(), 0);
        QVERIFY(!again.isModified());
        QCOMPARE(again.projectPath(), path);
        QCOMPARE(again.meshSpec(), dir.filePath("meshes/spot.obj"));
        QCOMPARE(again.styleText(), QString("<style><contour kind=\"visual\"/></style>"));
        QCOMPARE(style.count(), 1);
        QCOMPARE(QString::fromStdString(again.animation().pattern), sequence); // resolved against the project
        QCOMPARE(again.frame(), 7);
        QCOMPARE(again.view(), view(0.25, -0.125, 2.5));
        QCOMPARE(*again.light(), directional(0.5, 0.75, -1.0));
        // Saved again elsewhere, it writes what the first wrote there.
        const QString copy = dir.filePath("copy.snaxels");
        again.save(copy);
        doc.save(dir.filePath("first.snaxels"));
        QFile a(copy), b(dir.filePath("first.snaxels"));
        QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
        QCOMPARE(a.readAll(), b.readAll());
        // Undo after opening changes nothing: the history started there.
        QVERIFY(!again.undoStack()->canUndo());
    }

    void anEmptyStyleInAProjectIsTheDefaultStyle() {
        Project p;
        p.mesh = "proc:sphere";
        Document doc("<default-style/>");
        doc.load(p, "/nowhere/p.snaxels", "proc:sphere", nullptr);
        QCOMPARE(doc.styleText(), QString("<default-style/>"));
    }

    // The document is the one source of what is exported: its style (parsed
    // from its text), camera, light and animation, through every edit,
    // undo and redo, with a broken style text leaving the last good style.
    void theExportReadsTheDocument() {
        const QString visual = "<style version=\"1\"><contour kind=\"visual\"><visible stroke=\"#000000\" width=\"1\"/></contour></style>";
        const QString shaded = "<style version=\"1\"><canvas width=\"640\" height=\"480\"/><light dir=\"0,1,0\"/>"
                               "<contour kind=\"shadow\"><visible stroke=\"#202020\" width=\"2\"/></contour>"
                               "<contour kind=\"isophote\" k=\"0.5\"><visible stroke=\"#404040\" width=\"1\"/></contour></style>";
        Document doc(visual);
        QSignalSpy parsed(&doc, &Document::styleChanged);
        snaxels::AnimationJob job = doc.animationJob();
        QCOMPARE(job.scene.kinds.size(), std::size_t(1));
        QCOMPARE(int(job.scene.kinds[0].kind), int(snaxels::ContourKind::Visual));

        doc.setStyleText(shaded);
        QCOMPARE(parsed.count(), 1);
        job = doc.animationJob();
        QCOMPARE(job.scene.kinds.size(), std::size_t(2));
        QCOMPARE(int(job.scene.kinds[0].kind), int(snaxels::ContourKind::Shadow));
        QCOMPARE(job.scene.kinds[1].k, 0.5);
        QCOMPARE(job.scene.style.width, 640);
        QCOMPARE(job.scene.style.height, 480);
        // No light of the user's: the style's.
        QCOMPARE(job.scene.light.dir.y, 1.0);
        QCOMPARE(job.scene.light.dir.x, 0.0);

        // A text that does not parse is the document's text, but the style
        // in force stays the last that parsed.
        pastMergeWindow();
        doc.setStyleText("<style version=\"1\"><contour kind=");
        QCOMPARE(parsed.count(), 1);
        QCOMPARE(doc.animationJob().scene.kinds.size(), std::size_t(2));

        pastMergeWindow();
        doc.setLight(directional(1, 0, 0));
        job = doc.animationJob();
        QCOMPARE(job.scene.light.dir.x, 1.0); // the user's light wins over the style's
        QCOMPARE(job.scene.light.dir.y, 0.0);

        // The camera: frame 0 of the document's view, whatever it was turned by.
        OrbitView side = view(0.0, 0.0, 5.0);
        side.turntable = 1.0;
        doc.setView(side);
        job = doc.animationJob();
        QVERIFY(!job.scene.camera.orthographic());
        QVERIFY(std::abs(job.scene.camera.eye.x) < 1e-12);
        QVERIFY(std::abs(job.scene.camera.eye.y) < 1e-12);
        QVERIFY(std::abs(job.scene.camera.eye.z - 5.0) < 1e-12);

        AnimationSpec orbit;
        orbit.kind = AnimationSpec::Kind::LightOrbit;
        orbit.frames = 48;
        orbit.degrees_per_frame = 7.5;
        doc.setAnimation(orbit);
        job = doc.animationJob();
        QCOMPARE(int(job.animation.kind), int(AnimationSpec::Kind::LightOrbit));
        QCOMPARE(job.animation.frames, 48);
        QCOMPARE(job.animation.degrees_per_frame, 7.5);

        // Undo walks every part back, and the export follows.
        while (doc.undoStack()->canUndo()) doc.undoStack()->undo();
        job = doc.animationJob();
        QCOMPARE(job.scene.kinds.size(), std::size_t(1));
        QCOMPARE(int(job.scene.kinds[0].kind), int(snaxels::ContourKind::Visual));
        QCOMPARE(int(job.animation.kind), int(AnimationSpec().kind));
        QVERIFY(!doc.light().has_value());
        QCOMPARE(job.scene.style.width, snaxels::default_style().width);
        // And redo forward again (to the broken text, under the last style
        // that parsed).
        while (doc.undoStack()->canRedo()) doc.undoStack()->redo();
        job = doc.animationJob();
        QCOMPARE(job.scene.kinds.size(), std::size_t(2));
        QCOMPARE(job.scene.light.dir.x, 1.0);
        QCOMPARE(job.animation.frames, 48);
    }

    // The undo stack's steps, carried out on a fresh document from where
    // the history began, give the document's state at the stack's index,
    // after undo, redo, merges and changes that are not edits alike.
    void theHistoryReplaysOntoAFreshDocument() {
        Document doc("<style/>");
        doc.resetView(view(0.1, 0.2, 3.0)); // not an edit, with no history yet: where it begins
        QVERIFY(doc.historyStart().view == view(0.1, 0.2, 3.0));
        doc.setStyleText("<style><canvas width=\"300\"/></style>");
        pastMergeWindow();
        doc.setView(view(0.5, 0.2, 3.0));
        doc.setView(view(0.7, 0.1, 3.0)); // merges with the one before
        doc.setLight(directional(0, 1, 0));
        AnimationSpec spin;
        spin.kind = AnimationSpec::Kind::LightOrbit;
        doc.setAnimation(spin);
        const auto replayed = [&doc] {
            Document fresh("<other/>");
            fresh.restore(doc.historyStart());
            for (int i = 0; i < doc.undoStack()->index(); ++i)
                dynamic_cast<const snaxels::ui::DocumentStep*>(doc.undoStack()->command(i))->applyTo(fresh);
            return fresh.edited();
        };
        QCOMPARE(doc.undoStack()->count(), 4);
        QVERIFY(replayed() == doc.edited());
        doc.undoStack()->undo();
        doc.undoStack()->undo();
        QVERIFY(doc.edited().view == view(0.7, 0.1, 3.0));
        QVERIFY(!doc.edited().light.has_value());
        QVERIFY(replayed() == doc.edited());
        doc.undoStack()->undo();
        doc.undoStack()->undo();
        QCOMPARE(doc.edited().style, QString("<style/>"));
        QVERIFY(replayed() == doc.edited());
        doc.undoStack()->redo();
        QVERIFY(replayed() == doc.edited());
        // A change that is not an edit, with history: the start stays.
        doc.resetView(view(1.0, 0.0, 2.0));
        QVERIFY(doc.historyStart().view == view(0.1, 0.2, 3.0));
    }

    // The contour scheduler is busy until a computation's result has been
    // handed on: between the thread's end and the result's delivery it was
    // not, and the window called itself idle with a stale drawing.
    void theSchedulerIsBusyUntilTheResultIsHandedOn() {
        std::atomic<bool> started{false}, go{false}, done{false};
        snaxels::ui::ContourScheduler scheduler([&]() -> std::optional<snaxels::ui::ContourScheduler::Work> {
            return snaxels::ui::ContourScheduler::Work([&] {
                started = true;
                while (!go) std::this_thread::sleep_for(std::chrono::milliseconds(1));
                done = true;
                return snaxels::ui::OverlayResult{};
            });
        });
        QSignalSpy ready(&scheduler, &snaxels::ui::ContourScheduler::ready);
        scheduler.schedule();
        QVERIFY(scheduler.busy());
        QTRY_VERIFY(started.load());
        go = true;
        while (!done) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        std::this_thread::sleep_for(std::chrono::milliseconds(200)); // the thread ends; no event is handled
        QCOMPARE(ready.count(), 0);
        QVERIFY(scheduler.busy());
        QTRY_COMPARE(ready.count(), 1);
        QVERIFY(!scheduler.busy());
    }

    void aFailedSaveChangesNothing() {
        QTemporaryDir dir;
        Document doc("<style/>");
        doc.setMesh("proc:torus", nullptr);
        doc.setStyleText("<edited/>");
        const QString bad = dir.filePath("no-such-folder/p.snaxels");
        bool threw = false;
        try {
            doc.save(bad);
        } catch (const snaxels::Error& e) {
            threw = true;
            QVERIFY2(QString(e.what()).contains("no-such-folder"), e.what());
        }
        QVERIFY(threw);
        QVERIFY(doc.isModified());
        QVERIFY(doc.projectPath().isEmpty());
        QVERIFY(!QFile::exists(bad));
    }

    // A scene's animation as the document plays it: names filled in, a
    // clip's length at the rate, and what the scene lacks giving way.
    void resolvesTheAnimationAgainstTheScene() {
        snaxels::ui::SceneFacts facts;
        facts.clips = {{"Idle", 1.0}, {"Walk", 2.0}};
        snaxels::FileCamera still, moving;
        still.name = "Top";
        moving.name = "Shot";
        moving.clip = "ShotAction";
        moving.clip_seconds = 0.5;
        facts.cameras = {still, moving};
        AnimationSpec clip;
        clip.kind = AnimationSpec::Kind::Clip;
        clip.clip = "1"; // by number
        clip.frames = 0; // its own length
        clip.fps = 10.0;
        bool found = false;
        AnimationSpec r = snaxels::ui::resolve_animation(clip, facts, &found);
        QVERIFY(found);
        QCOMPARE(QString::fromStdString(r.clip), QString("Walk"));
        QCOMPARE(r.frames, 21); // 2 s at 10 fps, both ends
        clip.clip.clear(); // the first
        QCOMPARE(QString::fromStdString(snaxels::ui::resolve_animation(clip, facts).clip), QString("Idle"));
        clip.clip = "Run"; // not there: a turntable, told
        r = snaxels::ui::resolve_animation(clip, facts, &found);
        QVERIFY(!found);
        QCOMPARE(r.kind, AnimationSpec::Kind::Turntable);
        QVERIFY(r.clip.empty());
        QCOMPARE(r.frames, 1);
        AnimationSpec move;
        move.kind = AnimationSpec::Kind::Camera;
        move.camera = "Shot";
        move.frames = 0;
        move.fps = 24.0;
        r = snaxels::ui::resolve_animation(move, facts, &found);
        QVERIFY(found);
        QCOMPARE(QString::fromStdString(r.clip), QString("ShotAction"));
        QCOMPARE(r.frames, 13);
        move.camera = "Top"; // a camera no clip moves is no camera move
        r = snaxels::ui::resolve_animation(move, facts, &found);
        QVERIFY(!found);
        QCOMPARE(r.kind, AnimationSpec::Kind::Turntable);
        AnimationSpec through;
        through.kind = AnimationSpec::Kind::LightOrbit;
        through.camera = "Gone";
        through.frames = 30;
        r = snaxels::ui::resolve_animation(through, facts, &found);
        QVERIFY(!found);
        QVERIFY(r.camera.empty()); // the view's camera
        QCOMPARE(r.kind, AnimationSpec::Kind::LightOrbit);
        QCOMPARE(r.frames, 30);
    }

    // The frame stays within the animation, and follows it when it shortens.
    void theFrameStaysWithinTheAnimation() {
        Document doc("<style/>");
        AnimationSpec turn;
        turn.kind = AnimationSpec::Kind::Turntable;
        turn.frames = 10;
        doc.setAnimation(turn);
        doc.setFrame(25);
        QCOMPARE(doc.frame(), 9);
        doc.setFrame(-3);
        QCOMPARE(doc.frame(), 0);
        doc.setFrame(8);
        turn.frames = 5;
        QSignalSpy frame(&doc, &Document::frameChanged);
        doc.setAnimation(turn);
        QCOMPARE(doc.frame(), 4);
        QCOMPARE(frame.count(), 1);
        turn.start = 3;
        doc.setAnimation(turn);
        QCOMPARE(doc.sourceFrame(), 7);
    }

    // The document parses its style's text once per edit and keeps what
    // the parse found: the error's place, or the warnings.
    void theStyleIsParsedAndCheckedByTheDocument() {
        Document doc("<style version=\"1\"/>");
        QVERIFY(!doc.styleProblem());
        QSignalSpy checked(&doc, &Document::styleChecked);
        QSignalSpy parsed(&doc, &Document::styleChanged);
        doc.setStyleText("<style version=\"1\">\n  <contour kind=\"visual\" colour=\"red\"/>\n</style>");
        QCOMPARE(checked.count(), 1);
        QCOMPARE(parsed.count(), 1);
        QVERIFY(!doc.styleProblem());
        QCOMPARE(doc.styleWarnings().size(), std::size_t(1)); // an attribute the parser does not know
        QCOMPARE(doc.styleWarnings()[0].line, 2);
        pastMergeWindow();
        doc.setStyleText("<style version=\"1\">\n  <contour kind=\"nothing\"/>\n</style>");
        QCOMPARE(checked.count(), 2);
        QCOMPARE(parsed.count(), 1); // the last good style stays in force
        QVERIFY(doc.styleProblem().has_value());
        QCOMPARE(doc.styleProblem()->line, 2);
        QVERIFY(doc.styleWarnings().empty());
        QCOMPARE(doc.style().contours.size(), std::size_t(1));
    }


    // A save dialog starts in a folder that exists and can be written to:
    // a folder gone, or a file where a folder was, is passed over.
    void saveDialogsStartInAWritableFolder() {
        QTemporaryDir dir;
        QFile file(dir.filePath("not-a-folder"));
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.close();
        QCOMPARE(snaxels::ui::first_writable_folder({dir.filePath("gone"), file.fileName(), dir.path()}),
                 QFileInfo(dir.path()).absoluteFilePath());
        const QString fallback = snaxels::ui::first_writable_folder({dir.filePath("gone")});
        QVERIFY(QFileInfo(fallback).isDir() && QFileInfo(fallback).isWritable());
    }

};

QTEST_GUILESS_MAIN(TestDocument)
#include "test_document.moc"
