#pragma once
// The Export menu and what it does: the document's animation written as
// animated SVG, Lottie or video off the GUI thread (AnimationExport), and
// the frame on screen written as SVG or vector PDF. Save dialogs start in
// the folder last used for each kind of file; what was written is said in
// the status bar with a button that shows its folder.

#include <QByteArray>
#include <QObject>
#include <QString>

class QMainWindow;
class QToolButton;
class QWidget;

namespace snaxels::ui {

class AnimationExport;
class Document;
class DocumentController;

/// Where the dialogs for each kind of file were last (QSettings keys).
inline constexpr const char* kExportFolder = "paths/export";
inline constexpr const char* kStyleFolder = "paths/style";
/// A video export's frame width (0: the canvas's) and quality (FFmpeg's CRF;
/// -1: the format's default), as last chosen (QSettings keys).
inline constexpr const char* kVideoWidth = "video/width";
inline constexpr const char* kVideoCrf = "video/crf";

/// The first of @p folders that exists and can be written to, else the
/// user's documents folder, else home: where a save dialog may start (a
/// packaged model's folder is a system folder the user cannot write).
QString first_writable_folder(const QStringList& folders);

/// Where a save dialog for a kind of file starts: for exports, the export
/// folder of the preferences; the folder last used for the kind (the
/// QSettings key @p folderKey); the project's folder (@p projectPath, when
/// saved); the folder of @p meshSpec (a file); documents or home: the first
/// of these that can be written to. Named after the mesh, with @p extension.
QString suggested_save_path(const QString& meshSpec, const char* folderKey, const QString& extension,
                            const QString& projectPath = {});

/// Asks where to save a kind of file (starting at suggested_save_path), adds
/// the extension of the filter chosen when the name has none, and
/// remembers the folder; empty when cancelled.
QString ask_save_path(QWidget* parent, const QString& meshSpec, const QString& title, const char* folderKey,
                      const QString& extension, const QString& filter, const QString& projectPath = {});

class ExportActions : public QObject {
    Q_OBJECT
  public:
    /// Exports @p document (flushed by @p controller first) from @p window,
    /// whose status bar gets the reports.
    ExportActions(Document* document, DocumentController* controller, QMainWindow* window);
    /// Adds the Export menu to the window's menu bar.
    void addMenu();

    /// Exports the document's animation to @p path as its extension asks,
    /// with a progress dialog that can cancel (nothing is written then);
    /// ends with finished or failed.
    void exportAnimation(const QString& path);
    /// Writes the frame on screen (the SVG, or for a .pdf path the vector
    /// PDF) to @p path atomically.
    bool exportFrame(const QString& path);
    bool running() const;

    /// The frame on screen: its SVG, or why it cannot be drawn (@p problem,
    /// the SVG empty).
    void setFrame(QByteArray svg, QString problem);
    const QByteArray& frameSvg() const { return svg_; }
    const QString& frameProblem() const { return problem_; }

  signals:
    void finished(const QString& path);
    void failed(const QString& message);

  private:
    /// Asks where, then exports the animation (@p frame false) or the frame.
    void askAndExport(const QString& title, const QString& extension, const QString& filter, bool frame);
    /// Says in the status bar that @p path was written, in full, and offers
    /// to show its folder.
    void reportExported(const QString& path);
    /// Says why nothing was exported, in the status bar and a box.
    void refuse(const QString& message);
    /// Export > Page Setup: the style's paper, orientation, margin, fit or
    /// scale, asked and written into its <canvas> as one undo step.
    void askPageSetup();
    /// Asks a video's width and quality (kVideoWidth, kVideoCrf, as last
    /// chosen); false when cancelled.
    bool askVideoSettings(const QString& path);

    Document* document_;
    DocumentController* controller_;
    QMainWindow* window_;
    AnimationExport* export_;
    QToolButton* reveal_;
    QByteArray svg_;
    QString problem_;
};

} // namespace snaxels::ui
