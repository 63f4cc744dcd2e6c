#pragma once
// Undo steps of the document: each sets one part of it (the style text, the
// camera, the light, the animation) from one value to another, applying its
// value in redo (QUndoStack::push runs the first redo). Steps of the same
// kind in quick succession (wheel turns, spin-box clicks) merge into one.

#include <chrono>
#include <functional>
#include <utility>

#include <QUndoCommand>

namespace snaxels::ui {

/// Ids of mergeable steps; each value type has its own.
enum UndoId { kUndoStyle = 1, kUndoCamera, kUndoLight, kUndoAnimation };

template <class T>
class SetValueCommand : public QUndoCommand {
  public:
    /// Redo applies @p after through @p apply, undo @p before.
    SetValueCommand(const QString& text, int id, T before, T after, std::function<void(const T&)> apply,
                    bool mergeable = true)
        : QUndoCommand(text), id_(mergeable ? id : -1), before_(std::move(before)), after_(std::move(after)),
          apply_(std::move(apply)), stamp_(std::chrono::steady_clock::now()) {}

    void undo() override { apply_(before_); }
    void redo() override { apply_(after_); }
    int id() const override { return id_; }
    bool mergeWith(const QUndoCommand* other) override {
        const auto* o = static_cast<const SetValueCommand*>(other); // same id: same type
        if (o->stamp_ - stamp_ > std::chrono::milliseconds(1500)) return false;
        after_ = o->after_;
        stamp_ = o->stamp_;
        setObsolete(before_ == after_);
        return true;
    }

  private:
    int id_;
    T before_, after_;
    std::function<void(const T&)> apply_;
    std::chrono::steady_clock::time_point stamp_;
};

} // namespace snaxels::ui
