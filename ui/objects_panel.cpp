#include "ui/objects_panel.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <QComboBox>
#include <QToolButton>
#include <QMenu>
#include <QColorDialog>
#include <QHeaderView>
#include <QTimer>
#include <QScrollBar>
#include <QMainWindow>
#include <QDockWidget>
#include <QEvent>
#include <QPainter>
#include <QPixmap>
#include <QTreeWidget>
#include <QVBoxLayout>

#include "snaxels/animation/scene_settings.h"
#include "snaxels/mesh/parts.h"

namespace snaxels::ui {

namespace {

constexpr int kPartRole = Qt::UserRole;      // the object's or material's index
constexpr int kIsObjectRole = Qt::UserRole + 1;

bool matches_any(const std::vector<std::string>& patterns, const std::string& name, const std::string& path) {
    return std::any_of(patterns.begin(), patterns.end(),
                       [&](const std::string& p) { return glob_match(p, name) || glob_match(p, path); });
}

QIcon swatch(const glm::dvec4& colour) {
    QPixmap pixmap(14, 14);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    // The file's colours are linear: shown as a screen shows them (sRGB).
    painter.setBrush(QColor(srgb_byte(colour.r), srgb_byte(colour.g), srgb_byte(colour.b)));
    painter.setPen(QColor(90, 90, 90));
    painter.drawRect(1, 1, 11, 11);
    return QIcon(pixmap);
}

/// The style text a panel edit starts from: an empty text is the built-in
/// style, written out so that an element can join it.
std::string editable(const QString& text) {
    return text.trimmed().isEmpty() ? std::string("<style>\n  <contour kind=\"visual\"/>\n</style>\n") : text.toStdString();
}

const QStringList& state_names() {
    static const QStringList names{QObject::tr("Drawn"), QObject::tr("Occluder only"), QObject::tr("Hidden")};
    return names;
}

} // namespace

ObjectState object_state(const Style& style, const std::string& name, const std::string& path) {
    if (matches_any(style.hidden_objects, name, path)) return ObjectState::Hidden;
    if (matches_any(style.occluders, name, path)) return ObjectState::Occluder;
    return ObjectState::Drawn;
}

bool draws_intersections(const Style& style, const FaceParts& parts, std::uint32_t index) {
    for (const ContourSpec& spec : style_kinds(style)) {
        if (spec.kind != ContourKind::Intersection) continue;
        if (PartMatcher(spec.parts, &parts).object(index)) return true;
    }
    return false;
}

QSize ObjectsPanel::sizeHint() const {
    const int scrollBar = tree_->verticalScrollBar()->sizeHint().width();
    return {tree_->header()->length() + 2 * tree_->frameWidth() + scrollBar, QWidget::sizeHint().height()};
}

bool ObjectsPanel::event(QEvent* event) {
    // Put in a dock: fitted whenever its tab is raised (the dock says so;
    // a tabbed-away panel stays "visible").
    if (event->type() == QEvent::ParentChange)
        if (auto* dock = qobject_cast<QDockWidget*>(parentWidget()))
            connect(dock, &QDockWidget::visibilityChanged, this, &ObjectsPanel::dockShown, Qt::UniqueConnection);
    return QWidget::event(event);
}

void ObjectsPanel::dockShown(bool shown) {
    // After the layout has sized the columns to the rows shown.
    if (shown) QTimer::singleShot(0, this, &ObjectsPanel::fitDock);
}

void ObjectsPanel::fitDock() {
    auto* dock = qobject_cast<QDockWidget*>(parentWidget());
    auto* window = dock ? qobject_cast<QMainWindow*>(dock->parentWidget()) : nullptr;
    if (!window || !isVisible() || visibleRegion().isEmpty() || dock->isFloating()) return; // its tab raised
    const int wanted = std::min(sizeHint().width(), window->width() / 2);
    if (dock->width() < wanted) window->resizeDocks({dock}, {wanted}, Qt::Horizontal);
}

ObjectsPanel::ObjectsPanel(QWidget* parent) : QWidget(parent), tree_(new QTreeWidget(this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(tree_);
    tree_->setObjectName("objectsTree");
    tree_->setColumnCount(6);
    // The name first, elided in a narrow dock; how it is drawn beside it.
    tree_->setHeaderLabels({tr("Part"), tr("Drawn as"), tr("Faces"), tr("Line sets"), tr("Meets"), tr("Lines")});
    tree_->headerItem()->setToolTip(4, tr("Draw the object's intersection lines: where it passes into another object or "
                                          "into itself"));
    tree_->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    tree_->header()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    tree_->header()->setSectionResizeMode(2, QHeaderView::ResizeToContents);
    tree_->header()->setSectionResizeMode(3, QHeaderView::ResizeToContents);
    tree_->header()->setSectionResizeMode(4, QHeaderView::ResizeToContents);
    tree_->header()->setSectionResizeMode(5, QHeaderView::ResizeToContents);
    connect(tree_, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem* item, int column) {
        if (updating_ || column != 4 || !mesh_ || !parts_ || !item->data(0, kIsObjectRole).toBool()) return;
        const auto o = std::uint32_t(item->data(0, kPartRole).toInt());
        const SceneObject& obj = mesh_->objects[o];
        const bool on = item->checkState(4) == Qt::Checked;
        const QString name = QString::fromStdString(obj.name);
        const auto text = with_intersection_lines(editable(text_), obj.name, on);
        if (!text) {
            emit notice(tr("The style has an error: fix it in the Style tab first"));
            refreshStyle();
            return;
        }
        emit styleEdited(QString::fromStdString(*text),
                         on ? tr("Draw %1's Intersection Lines").arg(name) : tr("Leave Out %1's Intersection Lines").arg(name));
        // A line set that takes it among others (every object's) may still draw them.
        if (!on && draws_intersections(style_, *parts_, o)) {
            emit notice(tr("%1's intersection lines are still drawn: a line set in the style takes it").arg(name));
            refreshStyle();
        }
    });
    tree_->setTextElideMode(Qt::ElideMiddle);
    tree_->setRootIsDecorated(true);
    tree_->setToolTip(tr("The scene's objects and materials. Choose how an object is drawn: its lines drawn, kept as "
                         "an occluder that hides what is behind it, or hidden. Select a part to see it in the 3-D view."));
    connect(tree_, &QTreeWidget::itemSelectionChanged, this, &ObjectsPanel::emitHighlight);
    style_ = default_style();
}

void ObjectsPanel::setMesh(std::shared_ptr<const LoadedMesh> mesh) {
    mesh_ = std::move(mesh);
    parts_ = mesh_ ? loaded_parts(*mesh_) : nullptr; // once per mesh, not per style edit
    rebuild();
    if (isVisible()) QTimer::singleShot(0, this, &ObjectsPanel::fitDock); // other names, other widths
}

void ObjectsPanel::setStyle(const QString& text, const Style& style) {
    text_ = text;
    style_ = style;
    refreshStyle();
}

void ObjectsPanel::rebuild() {
    // Items made here (their check boxes set) are no user's edit.
    updating_ = true;
    tree_->clear();
    if (!mesh_ || mesh_->face_object.size() != mesh_->mesh.n_faces()) {
        updating_ = false;
        return;
    }
    std::vector<std::size_t> object_faces(mesh_->objects.size(), 0), material_faces(mesh_->materials.size(), 0);
    for (const std::uint32_t o : mesh_->face_object)
        if (o < object_faces.size()) ++object_faces[o];
    for (const std::uint32_t m : mesh_->face_material)
        if (m < material_faces.size()) ++material_faces[m];
    auto* objects = new QTreeWidgetItem(tree_, {tr("Objects (%1)").arg(mesh_->objects.size())});
    for (std::size_t o = 0; o < mesh_->objects.size(); ++o) {
        const SceneObject& object = mesh_->objects[o];
        auto* item = new QTreeWidgetItem(objects, {QString::fromStdString(object.name), QString(), QString::number(object_faces[o])});
        item->setToolTip(0, QString::fromStdString(object.path));
        item->setData(0, kPartRole, int(o));
        item->setData(0, kIsObjectRole, true);
        item->setTextAlignment(2, Qt::AlignRight | Qt::AlignVCenter);
        item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
        item->setCheckState(4, Qt::Unchecked);
        item->setToolTip(4, tr("Draw where %1 passes into another object or into itself").arg(QString::fromStdString(object.name)));
        auto* state = new QComboBox(tree_);
        state->setObjectName("state:" + QString::fromStdString(object.path));
        state->addItems(state_names());
        state->setToolTip(tr("How the style draws %1: its lines, as an occluder only (hiding what is behind it), or "
                             "not at all").arg(QString::fromStdString(object.name)));
        tree_->setItemWidget(item, 1, state);
        addLinesButton(item, o);
        connect(state, &QComboBox::activated, this, [this, o, state](int index) {
            if (updating_ || !mesh_) return;
            const SceneObject& obj = mesh_->objects[o];
            const auto wanted = ObjectState(index);
            const QString name = QString::fromStdString(obj.name);
            const auto text = with_object_drawing(editable(text_), obj.name, wanted);
            if (!text) {
                emit notice(tr("The style has an error: fix it in the Style tab first"));
                refreshStyle();
                return;
            }
            const QString step = wanted == ObjectState::Drawn      ? tr("Draw %1").arg(name)
                                 : wanted == ObjectState::Occluder ? tr("Make %1 an Occluder").arg(name)
                                                                   : tr("Hide %1").arg(name);
            emit styleEdited(QString::fromStdString(*text), step);
            // A pattern of the style that names it among others may still decide.
            if (object_state(style_, obj.name, obj.path) != wanted) {
                emit notice(tr("%1 is still %2: a pattern in the style sets it")
                                .arg(name, state_names()[int(object_state(style_, obj.name, obj.path))].toLower()));
                refreshStyle();
            }
        });
    }
    auto* materials = new QTreeWidgetItem(tree_, {tr("Materials (%1)").arg(mesh_->materials.size())});
    for (std::size_t m = 0; m < mesh_->materials.size(); ++m) {
        const SceneMaterial& material = mesh_->materials[m];
        auto* item = new QTreeWidgetItem(materials, {QString::fromStdString(material.name), QString(), QString::number(material_faces[m])});
        item->setIcon(0, swatch(material.colour));
        item->setData(0, kPartRole, int(m));
        item->setData(0, kIsObjectRole, false);
        item->setTextAlignment(2, Qt::AlignRight | Qt::AlignVCenter);
        item->setToolTip(0, tr("%1: colour %2 %3 %4, opacity %5")
                                .arg(QString::fromStdString(material.name))
                                .arg(material.colour.r, 0, 'g', 3)
                                .arg(material.colour.g, 0, 'g', 3)
                                .arg(material.colour.b, 0, 'g', 3)
                                .arg(material.colour.a, 0, 'g', 3));
    }
    tree_->expandAll();
    updating_ = false;
    refreshStyle();
}

void ObjectsPanel::addLinesButton(QTreeWidgetItem* item, std::size_t o) {
    const SceneObject& object = mesh_->objects[o];
    const QString name = QString::fromStdString(object.name);
    auto* button = new QToolButton(tree_);
    button->setObjectName("lines:" + QString::fromStdString(object.path));
    button->setText(tr("Lines"));
    button->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    button->setPopupMode(QToolButton::InstantPopup);
    button->setToolTip(tr("%1's outline in a colour, width and hidden lines of its own (a line set in the style)").arg(name));
    auto* menu = new QMenu(button);
    menu->addAction(tr("Colour…"), this, [this, o, name] {
        ObjectLines lines = linesOf(o).value_or(ObjectLines{});
        const QColor chosen = QColorDialog::getColor(QColor(QString::fromStdString(lines.colour)), this,
                                                     tr("%1's Lines").arg(name));
        if (!chosen.isValid()) return;
        lines.colour = chosen.name().toStdString();
        setLines(o, lines);
    })->setObjectName("linesColour");
    QMenu* widths = menu->addMenu(tr("Width"));
    for (const double w : {0.5, 1.0, 1.5, 2.0, 3.0, 4.0})
        widths->addAction(QString::number(w), this, [this, o, w] {
            ObjectLines lines = linesOf(o).value_or(ObjectLines{});
            lines.width = w;
            setLines(o, lines);
        })->setObjectName(QString("linesWidth%1").arg(w));
    menu->addAction(tr("Hidden Lines"), this, [this, o] {
        ObjectLines lines = linesOf(o).value_or(ObjectLines{});
        lines.hidden = !lines.hidden;
        setLines(o, lines);
    })->setObjectName("linesHidden");
    menu->addSeparator();
    menu->addAction(tr("As the Style Draws It"), this, [this, o] { setLines(o, std::nullopt); })->setObjectName("linesReset");
    button->setMenu(menu);
    tree_->setItemWidget(item, 5, button);
}

std::optional<ObjectLines> ObjectsPanel::linesOf(std::size_t o) const {
    const std::string& name = mesh_->objects[o].name;
    for (const ContourStyle& cs : style_.contours)
        if (cs.spec.kind == ContourKind::Visual && cs.spec.parts.objects == std::vector<std::string>{name} &&
            cs.spec.parts.materials.empty() && !cs.spec.parts.over_objects)
            return ObjectLines{cs.visible.colour, cs.visible.width, cs.hidden.draw};
    return std::nullopt;
}

void ObjectsPanel::setLines(std::size_t o, const std::optional<ObjectLines>& lines) {
    if (!mesh_ || o >= mesh_->objects.size()) return;
    const QString name = QString::fromStdString(mesh_->objects[o].name);
    const auto text = with_object_lines(editable(text_), mesh_->objects[o].name, lines);
    if (!text) {
        emit notice(tr("The style has an error: fix it in the Style tab first"));
        return;
    }
    emit styleEdited(QString::fromStdString(*text),
                     lines ? tr("Restyle %1's Lines").arg(name) : tr("Draw %1's Lines as the Style Does").arg(name));
}

void ObjectsPanel::refreshStyle() {
    if (!mesh_ || tree_->topLevelItemCount() < 2 || !parts_) return;
    const std::shared_ptr<const FaceParts>& parts = parts_;
    // Per line set, which objects and materials it takes.
    std::vector<PartMatcher> sets;
    std::vector<QString> labels;
    const std::vector<ContourSpec> kinds = style_kinds(style_);
    for (const ContourSpec& spec : kinds) {
        sets.emplace_back(spec.parts, parts.get());
        labels.push_back(QString::fromStdString(spec.label()));
    }
    // The materials each object has, and the objects each material is on.
    std::vector<std::set<std::uint32_t>> object_materials(parts->objects.size()), material_objects(parts->materials.size());
    for (const FaceId f : parts->object.ids()) {
        const std::uint32_t o = parts->object[f], m = parts->material[f];
        if (o < object_materials.size()) object_materials[o].insert(m);
        if (m < material_objects.size()) material_objects[m].insert(o);
    }
    updating_ = true;
    for (int top = 0; top < 2; ++top) {
        QTreeWidgetItem* group = tree_->topLevelItem(top);
        for (int i = 0; i < group->childCount(); ++i) {
            QTreeWidgetItem* item = group->child(i);
            const auto index = std::uint32_t(item->data(0, kPartRole).toInt());
            const bool is_object = item->data(0, kIsObjectRole).toBool();
            QStringList taking;
            for (std::size_t s = 0; s < sets.size(); ++s) {
                bool takes = false;
                for (const std::uint32_t other : is_object ? object_materials[index] : material_objects[index])
                    takes = takes || (is_object ? sets[s].object(index) && sets[s].material(other)
                                                : sets[s].object(other) && sets[s].material(index));
                if (takes) taking << labels[s];
            }
            if (is_object) {
                const SceneObject& object = parts->objects[index];
                const ObjectState state = object_state(style_, object.name, object.path);
                if (auto* combo = qobject_cast<QComboBox*>(tree_->itemWidget(item, 1))) combo->setCurrentIndex(int(state));
                item->setCheckState(4, draws_intersections(style_, *parts, index) ? Qt::Checked : Qt::Unchecked);
                if (state != ObjectState::Drawn) taking.clear();
            }
            item->setText(3, taking.isEmpty() ? tr("none") : taking.join(", "));
        }
    }
    updating_ = false;
}

void ObjectsPanel::emitHighlight() {
    std::vector<glm::vec3> triangles;
    const QList<QTreeWidgetItem*> selected = tree_->selectedItems();
    if (mesh_ && !selected.isEmpty() && selected.front()->parent()) {
        const QTreeWidgetItem* item = selected.front();
        const auto index = std::uint32_t(item->data(0, kPartRole).toInt());
        const bool is_object = item->data(0, kIsObjectRole).toBool();
        const std::vector<std::uint32_t>& of = is_object ? mesh_->face_object : mesh_->face_material;
        const Mesh& mesh = mesh_->mesh;
        for (const auto fh : mesh.faces()) {
            if (slot(fh) >= of.size() || of[slot(fh)] != index) continue;
            for (const auto vh : mesh.fv_range(fh)) triangles.push_back(glm::vec3(to_glm(mesh.point(vh))));
        }
    }
    emit highlightChanged(triangles);
}

} // namespace snaxels::ui
