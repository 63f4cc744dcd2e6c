#include "ui/preferences.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>

#include "snaxels/style/style.h"
#include "snaxels/style/style_edit.h"
#include "ui/styleeditor.h"

namespace snaxels::ui {
namespace {

const char* const kUnits[] = {"m", "cm", "mm", "in", "ft"};

/// The text of the style file at @p path, checked: empty and @p problem set
/// when it cannot be read or does not parse.
QString read_style_file(const QString& path, QString* problem) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        if (problem) *problem = QObject::tr("%1: cannot read it (%2)").arg(path, file.errorString());
        return {};
    }
    const QString text = QString::fromUtf8(file.readAll());
    try {
        parse_style(text.toStdString(), path.toStdString(), nullptr);
    } catch (const std::exception& e) {
        if (problem) *problem = QString::fromStdString(e.what());
        return {};
    }
    return text;
}

/// A row of a line edit and a Browse button that fills it.
QHBoxLayout* browse_row(QWidget* parent, QLineEdit* edit, bool folder) {
    auto* row = new QHBoxLayout;
    row->addWidget(edit, 1);
    auto* browse = new QPushButton(QObject::tr("Browse…"), parent);
    QObject::connect(browse, &QPushButton::clicked, parent, [parent, edit, folder] {
        const QString chosen = folder ? QFileDialog::getExistingDirectory(parent, QObject::tr("Export Folder"), edit->text())
                                      : QFileDialog::getOpenFileName(parent, QObject::tr("Default Style"), edit->text(),
                                                                     QObject::tr("Style (*.xml)"));
        if (!chosen.isEmpty()) edit->setText(chosen);
    });
    row->addWidget(browse);
    return row;
}

} // namespace

QString preferred_style_text(QString* problem) {
    const QSettings settings;
    const QString path = settings.value(kPrefStyle).toString();
    QString text = path.isEmpty() ? QString() : read_style_file(path, problem);
    if (text.isEmpty()) text = initial_style_text();
    const QString angle = settings.value(kPrefSharpAngle, "file").toString();
    if (angle != "file")
        if (const auto splice = sharp_angle_splice(text.toStdString(), angle.toStdString()))
            text = QString::fromStdString(splice->applied_to(text.toStdString()));
    return text;
}

QString preferred_model_units() {
    const QString units = QSettings().value(kPrefModelUnits, "m").toString();
    for (const char* u : kUnits)
        if (units == u) return units;
    return QStringLiteral("m");
}

PreferencesDialog::PreferencesDialog(QWidget* parent) : QDialog(parent) {
    setObjectName("preferences");
    setWindowTitle(tr("Preferences"));
    const QSettings settings;
    auto* form = new QFormLayout(this);
    style_ = new QLineEdit(settings.value(kPrefStyle).toString(), this);
    style_->setObjectName("prefStyle");
    style_->setPlaceholderText(tr("the built-in default"));
    style_->setToolTip(tr("An XML style file new documents start with (docs/styles.md); empty: the default"));
    form->addRow(tr("Default &style:"), browse_row(this, style_, false));

    sharp_ = new QComboBox(this);
    sharp_->setObjectName("prefSharpAngle");
    sharp_->setEditable(true);
    sharp_->addItem(tr("From the file's normals"), "file");
    for (const char* a : {"20", "30", "45", "60", "180"}) sharp_->addItem(tr("%1°").arg(a), a);
    const QString angle = settings.value(kPrefSharpAngle, "file").toString();
    sharp_->setCurrentIndex(std::max(sharp_->findData(angle), 0));
    if (sharp_->findData(angle) < 0) sharp_->setEditText(angle);
    sharp_->setToolTip(tr("Edges shaded hard in new documents (the style's <surface sharp-angle>): from the "
                          "file's normals, or past an angle in degrees (180: none)"));
    form->addRow(tr("S&harp edges:"), sharp_);

    units_ = new QComboBox(this);
    units_->setObjectName("prefModelUnits");
    for (const char* u : kUnits) units_->addItem(QString::fromLatin1(u), QString::fromLatin1(u));
    units_->setCurrentIndex(units_->findData(preferred_model_units()));
    units_->setToolTip(tr("The length of the model's unit, which Page Setup's scale of 1:N measures by"));
    form->addRow(tr("Model &units:"), units_);

    exportFolder_ = new QLineEdit(settings.value(kPrefExportFolder).toString(), this);
    exportFolder_->setObjectName("prefExportFolder");
    exportFolder_->setPlaceholderText(tr("the last one used, else the project's"));
    form->addRow(tr("&Export folder:"), browse_row(this, exportFolder_, true));

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, [this] {
        if (apply()) accept();
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);
}

bool PreferencesDialog::apply() {
    const QString style = style_->text().trimmed();
    QString problem;
    if (!style.isEmpty() && read_style_file(style, &problem).isEmpty()) {
        QMessageBox::warning(this, tr("Preferences"), tr("The default style cannot be used: %1").arg(problem));
        return false;
    }
    // A choice of the list, or an angle typed.
    const int listed = sharp_->findText(sharp_->currentText());
    const QString angle = listed >= 0 ? sharp_->itemData(listed).toString() : sharp_->currentText().remove(QChar(0x00b0)).trimmed();
    bool number = false;
    const double degrees = angle.toDouble(&number);
    if (angle != "file" && (!number || degrees < 0.0 || degrees > 180.0)) {
        QMessageBox::warning(this, tr("Preferences"), tr("Sharp edges: \"%1\" is not an angle from 0 to 180 degrees").arg(angle));
        return false;
    }
    const QString folder = exportFolder_->text().trimmed();
    if (!folder.isEmpty() && !QFileInfo(folder).isDir()) {
        QMessageBox::warning(this, tr("Preferences"), tr("The export folder %1 is not a folder").arg(folder));
        return false;
    }
    QSettings settings;
    settings.setValue(kPrefStyle, style);
    settings.setValue(kPrefSharpAngle, angle);
    settings.setValue(kPrefModelUnits, units_->currentData().toString());
    settings.setValue(kPrefExportFolder, folder);
    return true;
}

} // namespace snaxels::ui
