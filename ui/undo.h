#pragma once
// Undo steps of the document: each sets one part of it (the style text, the
// camera, the light, the animation) from one value to another, applying its
// value in redo (QUndoStack::push runs the first redo). Steps of the same
// kind in quick succession (wheel turns, spin-box clicks) merge into one.

#include <chrono>
#include <utility>

#include <QUndoCommand>

#include "ui/document.h"

namespace snaxels::ui {

/// Ids of mergeable steps; each value type has its own.
enum UndoId { kUndoStyle = 1, kUndoCamera, kUndoLight, kUndoAnimation };

/// A step on a document's undo stack, which can also be carried out on
/// another document (replaying a history onto a fresh document must give
/// the state the stack stands at).
class DocumentStep : public QUndoCommand {
  public:
    using QUndoCommand::QUndoCommand;
    /// Sets on @p other what redo sets on this step's document (no undo step there).
    virtual void applyTo(Document& other) const = 0;
};

template <class T>
class SetValueCommand : public DocumentStep {
  public:
    using Assign = void (Document::*)(const T&);
    /// Redo applies @p after to @p document through @p assign, undo @p before.
    SetValueCommand(const QString& text, int id, T before, T after, Document* document, Assign assign,
                    bool mergeable = true)
        : DocumentStep(text), id_(mergeable ? id : -1), before_(std::move(before)), after_(std::move(after)),
          document_(document), assign_(assign), stamp_(std::chrono::steady_clock::now()) {}

    void undo() override { (document_->*assign_)(before_); }
    void redo() override { (document_->*assign_)(after_); }
    void applyTo(Document& other) const override { (other.*assign_)(after_); }
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
    Document* document_;
    Assign assign_;
    std::chrono::steady_clock::time_point stamp_;
};

} // namespace snaxels::ui
