#pragma once
/// The one store of quantities derived from a mesh pose (curvature tensors
/// with their gradient operator, parabolic curves, ...), and of those of
/// its connectivity alone: each is computed by the first caller that
/// requires it and kept, under a key that names the quantity and every
/// option that changes its value, for as long as the pose (or the
/// connectivity) lives. Every frame, thread and copy of a topology in that
/// pose reads the same value. The stages say what they need through their
/// own `require_...(topology, options)` functions; this is their storage.
///
/// A key is typed (Quantity<T>): the value it names is a T, asked for and
/// kept as one without a cast at the call site, so a stage cannot read a
/// value as another type than the one kept (a key of another type does
/// not compile in its place, and the store checks the type it kept under
/// a name before it hands the value back).

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <type_traits>
#include <typeindex>
#include <typeinfo>
#include <utility>

#include "snaxels/error.h"

namespace snaxels {

/// The key of a quantity whose value is a @p T: its name, with every
/// option that changes the value.
template <class T> struct Quantity {
    using Value = T;
    std::string name;
};

class PoseQuantities {
  public:
    /// Whether a value is kept for as long as the pose lives only, or is
    /// also handed to the poses made from this one (MeshTopology::posed):
    /// a quantity defined on the connectivity (the parabolic curves, found
    /// once and carried by the edges as the mesh moves) is carried.
    enum class Lifetime { Pose, CarriedToLaterPoses };

    PoseQuantities() = default;
    /// A copy starts empty: a copied pose's positions may change before use.
    PoseQuantities(const PoseQuantities&) {}
    PoseQuantities& operator=(const PoseQuantities&) { return *this; }

    /// The value kept under @p key, or null.
    template <class T> std::shared_ptr<const T> find(const Quantity<T>& key) const {
        const std::lock_guard lock(mutex_);
        const auto it = values_.find(key.name);
        if (it == values_.end()) return nullptr;
        check_type<T>(key.name, it->second);
        return std::static_pointer_cast<const T>(it->second.value);
    }

    /// Keeps @p value under @p key unless a value is kept there already;
    /// returns the kept one.
    template <class T>
    std::shared_ptr<const T> keep(const Quantity<T>& key, std::shared_ptr<const T> value,
                                  Lifetime lifetime = Lifetime::Pose) const {
        const std::lock_guard lock(mutex_);
        const auto kept = values_.try_emplace(key.name, Entry{std::move(value), typeid(T), lifetime}).first;
        check_type<T>(key.name, kept->second);
        return std::static_pointer_cast<const T>(kept->second.value);
    }

    /// The value under @p key, computed by @p compute (returning a T, or a
    /// shared_ptr to one) when none is kept. Computed outside the lock, so
    /// two first callers may both compute it; the first to finish is kept.
    template <class T, class Compute>
    std::shared_ptr<const T> require(const Quantity<T>& key, Compute&& compute,
                                     Lifetime lifetime = Lifetime::Pose) const {
        if (auto kept = find(key)) return kept;
        return keep(key, std::shared_ptr<const T>(make_value<T>(std::forward<Compute>(compute))), lifetime);
    }

    /// Keeps in @p to every value of this store that is carried to later
    /// poses and that @p to lacks.
    void carry_to(const PoseQuantities& to) const {
        if (&to == this) return;
        std::map<std::string, Entry> carried;
        {
            const std::lock_guard lock(mutex_);
            for (const auto& [key, entry] : values_)
                if (entry.lifetime == Lifetime::CarriedToLaterPoses) carried.emplace(key, entry);
        }
        if (carried.empty()) return;
        const std::lock_guard lock(to.mutex_);
        for (auto& [key, entry] : carried) to.values_.try_emplace(key, std::move(entry));
    }

  private:
    struct Entry {
        std::shared_ptr<const void> value;
        std::type_index type; ///< what value points to
        Lifetime lifetime = Lifetime::Pose;
    };
    template <class T> static void check_type(const std::string& name, const Entry& entry) {
        if (entry.type != std::type_index(typeid(T)))
            throw InternalError("the quantity '" + name + "' is kept as " + entry.type.name() + ", asked for as " +
                                typeid(T).name());
    }
    template <class T, class Compute> static std::shared_ptr<const T> make_value(Compute&& compute) {
        using Result = decltype(compute());
        if constexpr (std::is_convertible_v<Result, std::shared_ptr<const T>>)
            return compute();
        else
            return std::make_shared<const T>(compute());
    }

    mutable std::mutex mutex_;
    mutable std::map<std::string, Entry> values_;
};

} // namespace snaxels
