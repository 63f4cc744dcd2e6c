#pragma once
// Edit > Preferences: what a new document starts with and where exports go,
// kept in QSettings. The style a new document starts with (a style file of
// the user's, else the built-in default) and its sharp angle; the model's
// unit that Page Setup's scale measures by default; the folder export
// dialogs start in (else the last one used, the project's or the mesh's).

#include <QDialog>
#include <QString>

class QComboBox;
class QLineEdit;

namespace snaxels::ui {

/// QSettings keys of the preferences.
inline constexpr const char* kPrefStyle = "prefs/style";             ///< a style file's path; empty: the default
inline constexpr const char* kPrefSharpAngle = "prefs/sharpAngle";   ///< "file" or degrees
inline constexpr const char* kPrefModelUnits = "prefs/modelUnits";   ///< m, cm, mm, in or ft
inline constexpr const char* kPrefExportFolder = "prefs/exportFolder"; ///< empty: the last one used

/// The style text a new document starts with: the preferred style file's
/// (when it reads and parses; else the built-in default, and @p problem
/// says why), with the preferred sharp angle set in its <surface>.
QString preferred_style_text(QString* problem = nullptr);

/// The model unit Page Setup's scale starts with (m by default).
QString preferred_model_units();

class PreferencesDialog : public QDialog {
    Q_OBJECT
  public:
    explicit PreferencesDialog(QWidget* parent = nullptr);
    /// Writes the choices to QSettings, checking the style file first;
    /// false (and a message) when it does not read as a style.
    bool apply();

  private:
    QLineEdit* style_;
    QComboBox* sharp_;
    QComboBox* units_;
    QLineEdit* exportFolder_;
};

} // namespace snaxels::ui
