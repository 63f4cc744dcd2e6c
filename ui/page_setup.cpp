#include "ui/page_setup.h"

#include <cmath>

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>

#include "snaxels/style/style.h"
#include "ui/preferences.h"

namespace snaxels::ui {
namespace {

/// The named papers the dialog offers, as paper_size() knows them.
const char* const kPapers[] = {"A0", "A1", "A2", "A3", "A4", "A5", "A6", "B4", "B5", "letter", "legal", "tabloid"};
const char* const kModelUnits[] = {"m", "cm", "mm", "in", "ft"};

QString number(double v) { return QString::number(v, 'g', 10); }

} // namespace

PageSetupDialog::PageSetupDialog(const Style& style, QWidget* parent) : QDialog(parent) {
    setObjectName("pageSetup");
    setWindowTitle(tr("Page Setup"));
    auto* form = new QFormLayout(this);
    const Page& page = style.page;
    hadPaper_ = page.paper();

    paper_ = new QComboBox(this);
    paper_->setObjectName("paper");
    paper_->addItem(tr("None: a canvas of %1 × %2 pixels").arg(style.width).arg(style.height), QString());
    for (const char* name : kPapers) {
        const glm::dvec2 mm = *paper_size(name);
        const QString label = QString::fromLatin1(name);
        paper_->addItem(tr("%1 (%2 × %3 mm)").arg(label.left(1).toUpper() + label.mid(1), number(mm.x), number(mm.y)),
                        QString::fromLatin1(name));
    }
    paper_->addItem(tr("Custom"), QStringLiteral("custom"));
    form->addRow(tr("&Paper:"), paper_);

    auto* custom = new QHBoxLayout;
    customWidth_ = new QDoubleSpinBox(this);
    customHeight_ = new QDoubleSpinBox(this);
    for (QDoubleSpinBox* box : {customWidth_, customHeight_}) {
        box->setRange(1.0, 5000.0);
        box->setDecimals(2);
        custom->addWidget(box);
    }
    customWidth_->setObjectName("customWidth");
    customHeight_->setObjectName("customHeight");
    custom->insertWidget(1, new QLabel(QStringLiteral("×"), this));
    customUnit_ = new QComboBox(this);
    customUnit_->addItem(tr("mm"), QStringLiteral("mm"));
    customUnit_->addItem(tr("in"), QStringLiteral("in"));
    custom->addWidget(customUnit_);
    form->addRow(tr("Custom size:"), custom);

    orientation_ = new QComboBox(this);
    orientation_->setObjectName("orientation");
    orientation_->addItem(tr("Portrait"), QStringLiteral("portrait"));
    orientation_->addItem(tr("Landscape"), QStringLiteral("landscape"));
    form->addRow(tr("&Orientation:"), orientation_);

    margin_ = new QDoubleSpinBox(this);
    margin_->setObjectName("margin");
    margin_->setRange(0.0, 200.0);
    margin_->setSuffix(tr(" mm"));
    margin_->setToolTip(tr("The border the drawing stays inside"));
    form->addRow(tr("&Margin:"), margin_);

    size_ = new QComboBox(this);
    size_->setObjectName("size");
    size_->addItem(tr("Fit: all of the view inside the page"), QStringLiteral("fit"));
    size_->addItem(tr("Fill: the page covered, the view cropped"), QStringLiteral("fill"));
    size_->addItem(tr("To scale (orthographic views)"), QStringLiteral("scale"));
    form->addRow(tr("&Size:"), size_);

    auto* scaleRow = new QHBoxLayout;
    scaleRow->addWidget(new QLabel(QStringLiteral("1 :"), this));
    scale_ = new QDoubleSpinBox(this);
    scale_->setObjectName("scale");
    scale_->setRange(0.001, 1e6);
    scale_->setDecimals(3);
    scaleRow->addWidget(scale_, 1);
    units_ = new QComboBox(this);
    units_->setObjectName("modelUnits");
    for (const char* u : kModelUnits) units_->addItem(tr("model unit = 1 %1").arg(QString::fromLatin1(u)), QString::fromLatin1(u));
    scaleRow->addWidget(units_);
    form->addRow(tr("S&cale:"), scaleRow);

    summary_ = new QLabel(this);
    summary_->setObjectName("pageSummary");
    summary_->setWordWrap(true);
    form->addRow(summary_);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);

    showPage(style);
    for (QComboBox* box : {paper_, customUnit_, orientation_, size_, units_})
        connect(box, &QComboBox::currentIndexChanged, this, &PageSetupDialog::update);
    for (QDoubleSpinBox* box : {customWidth_, customHeight_, margin_, scale_})
        connect(box, &QDoubleSpinBox::valueChanged, this, &PageSetupDialog::update);
    update();
}

void PageSetupDialog::showPage(const Style& style) {
    const Page& page = style.page;
    customWidth_->setValue(page.paper() ? page.width_mm : 210.0);
    customHeight_->setValue(page.paper() ? page.height_mm : 297.0);
    if (page.paper()) {
        int found = paper_->count() - 1; // custom, unless a named size matches either way round
        for (int i = 1; i + 1 < paper_->count(); ++i) {
            const glm::dvec2 mm = *paper_size(paper_->itemData(i).toString().toStdString());
            if (std::abs(std::min(page.width_mm, page.height_mm) - mm.x) < 1e-6 &&
                std::abs(std::max(page.width_mm, page.height_mm) - mm.y) < 1e-6)
                found = i;
        }
        paper_->setCurrentIndex(found);
        orientation_->setCurrentIndex(page.width_mm > page.height_mm ? 1 : 0);
        margin_->setValue(style.margin / kPixelsPerMm);
    } else {
        paper_->setCurrentIndex(0);
        margin_->setValue(10.0);
    }
    size_->setCurrentIndex(page.scale > 0.0 ? 2 : page.fit == Page::Fit::Fill ? 1 : 0);
    scale_->setValue(page.scale > 0.0 ? page.scale : 50.0);
    // The page's unit when it has a scale, else the preferences'.
    units_->setCurrentIndex(std::max(units_->findData(preferred_model_units()), 0));
    for (int i = 0; page.scale > 0.0 && i < units_->count(); ++i)
        if (*model_unit_mm(units_->itemData(i).toString().toStdString()) == page.unit_mm) units_->setCurrentIndex(i);

}

void PageSetupDialog::update() {
    const QString paper = paper_->currentData().toString();
    const bool onPaper = !paper.isEmpty(), custom = paper == "custom", scaled = size_->currentData() == "scale";
    for (QWidget* w : {static_cast<QWidget*>(customWidth_), static_cast<QWidget*>(customHeight_),
                       static_cast<QWidget*>(customUnit_)})
        w->setEnabled(custom);
    orientation_->setEnabled(onPaper);
    margin_->setEnabled(onPaper);
    scale_->setEnabled(scaled);
    units_->setEnabled(scaled);
    if (!onPaper) {
        summary_->setText(tr("The drawing keeps its canvas of pixels; PDF pages are a point a pixel."));
        return;
    }
    const double unit = customUnit_->currentData() == "in" ? 25.4 : 1.0;
    glm::dvec2 mm = custom ? glm::dvec2(customWidth_->value() * unit, customHeight_->value() * unit)
                           : *paper_size(paper.toStdString());
    const bool landscape = orientation_->currentData() == "landscape";
    const double w = landscape ? std::max(mm.x, mm.y) : std::min(mm.x, mm.y), h = landscape ? std::min(mm.x, mm.y) : std::max(mm.x, mm.y);
    QString text = tr("A page of %1 × %2 mm (%3 × %4 pixels at 96 to the inch).")
                       .arg(number(std::round(w * 10) / 10), number(std::round(h * 10) / 10))
                       .arg(std::lround(w * kPixelsPerMm))
                       .arg(std::lround(h * kPixelsPerMm));
    if (scaled)
        text += tr(" At 1:%1 a model unit (%2) is drawn %3 mm long.")
                    .arg(number(scale_->value()), units_->currentData().toString(),
                         number(std::round(*model_unit_mm(units_->currentData().toString().toStdString()) / scale_->value() * 1000) / 1000));
    summary_->setText(text);
}

CanvasAttributes PageSetupDialog::attributes() const {
    CanvasAttributes out;
    const QString paper = paper_->currentData().toString();
    const QString size = size_->currentData().toString();
    if (paper.isEmpty()) {
        out = {{"paper", std::nullopt}, {"orientation", std::nullopt}};
        if (hadPaper_) out.push_back({"margin", std::nullopt}); // the page's margin: back to the canvas's default
    } else {
        std::string name = paper.toStdString();
        if (paper == "custom")
            name = (number(customWidth_->value()) + "x" + number(customHeight_->value()) + customUnit_->currentData().toString())
                       .toStdString();
        out = {{"width", std::nullopt},
               {"height", std::nullopt},
               {"paper", name},
               {"orientation", orientation_->currentData().toString().toStdString()},
               {"margin", (number(margin_->value()) + "mm").toStdString()}};
    }
    out.push_back({"fit", size == "fill" ? std::optional<std::string>("fill") : std::nullopt});
    out.push_back({"scale", size == "scale" ? std::optional<std::string>("1:" + number(scale_->value()).toStdString()) : std::nullopt});
    const std::string units = units_->currentData().toString().toStdString();
    out.push_back({"model-units", size == "scale" && units != "m" ? std::optional<std::string>(units) : std::nullopt});
    return out;
}

} // namespace snaxels::ui
