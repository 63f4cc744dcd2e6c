#pragma once
// Undo steps of the document: each sets one part of it (the style text, the
// camera, the light, the animation) from one value to another. Steps of the
// same kind in quick succession (wheel turns, spin-box clicks) merge into one.

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
    /// The change has already happened when the command is pushed: the
    /// first redo does nothing; undo and later redos call @p apply.
    SetValueCommand(const QString& text, int id, T before, T after, std::function<void(const T&)> apply,
                    bool mergeable = true)
        : QUndoCommand(text), id_(mergeable ? id : -1), before_(std::move(before)), after_(std::move(after)),
          apply_(std::move(apply)), stamp_(std::chrono::steady_clock::now()) {}

    void undo() override { apply_(before_); }
    void redo() override {
        if (first_) first_ = false;
        else apply_(after_);
    }
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
    bool first_ = true;
};

} // namespace snaxels::ui
