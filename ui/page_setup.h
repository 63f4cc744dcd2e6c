#pragma once
// Export > Page Setup: the paper a drawing is made for (a size from the A
// series, Letter, Legal, Tabloid or a custom one, or none: a canvas of
// pixels), its orientation and margin, and whether the view fits the page,
// fills it or is drawn to a scale of 1:N in the model's units. Its answer is
// the style's <canvas> attributes (docs/styles.md), so the page is part of
// the style: in the XML, in the project, one undo step.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <QDialog>

#include "snaxels/style/page.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;

namespace snaxels::ui {

/// What a page setup writes: <canvas> attributes set (a value) or removed.
using CanvasAttributes = std::vector<std::pair<std::string, std::optional<std::string>>>;

class PageSetupDialog : public QDialog {
    Q_OBJECT
  public:
    /// Shows @p style's page (its paper, margin, fit or scale).
    PageSetupDialog(const Style& style, QWidget* parent = nullptr);
    /// The <canvas> attributes the choices make.
    CanvasAttributes attributes() const;

  private:
    /// Sets the choices to @p style's page.
    void showPage(const Style& style);
    /// Enables what the choices allow and says what the page will be.
    void update();

    QComboBox* paper_;
    QDoubleSpinBox* customWidth_;
    QDoubleSpinBox* customHeight_;
    QComboBox* customUnit_;
    QComboBox* orientation_;
    QDoubleSpinBox* margin_;
    QComboBox* size_;
    QDoubleSpinBox* scale_;
    QComboBox* units_;
    QLabel* summary_;
    bool hadPaper_ = false;
};

} // namespace snaxels::ui
