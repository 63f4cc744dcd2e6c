// The store of derived quantities (snaxels/mesh/quantities.h): a value is
// computed once per key and shared; a key carries its value's type, so a
// value cannot be read as another type, at compile time through the key
// and at run time where two keys of one name disagree.

#include <gtest/gtest.h>

#include <concepts>
#include <memory>
#include <string>
#include <vector>

#include "snaxels/error.h"
#include "snaxels/mesh/quantities.h"

namespace {

using snaxels::PoseQuantities;
using snaxels::Quantity;

/// Whether the store's find, given a key of type @p Key, hands back a @p T.
template <class Key, class T>
concept FindsAs = requires(const PoseQuantities& q, const Key& key) {
    { q.find(key) } -> std::same_as<std::shared_ptr<const T>>;
};
static_assert(FindsAs<Quantity<double>, double>);
static_assert(!FindsAs<Quantity<double>, int>);
static_assert(!FindsAs<std::string, double>); // a bare name is no key

TEST(Quantities, ComputedOnceAndShared) {
    PoseQuantities store;
    int computed = 0;
    const Quantity<std::vector<int>> key{"numbers n=3"};
    const auto a = store.require(key, [&] {
        ++computed;
        return std::vector<int>{1, 2, 3};
    });
    const auto b = store.require(key, [&] {
        ++computed;
        return std::vector<int>{};
    });
    EXPECT_EQ(computed, 1);
    EXPECT_EQ(a, b);
    EXPECT_EQ(a->size(), 3u);
    EXPECT_EQ(store.find(Quantity<std::vector<int>>{"numbers n=4"}), nullptr);
}

TEST(Quantities, ANameKeptAsOneTypeIsNotReadAsAnother) {
    PoseQuantities store;
    store.require(Quantity<double>{"feature size"}, [] { return 0.25; });
    EXPECT_THROW(store.find(Quantity<float>{"feature size"}), snaxels::InternalError);
    EXPECT_THROW(store.require(Quantity<int>{"feature size"}, [] { return 1; }), snaxels::InternalError);
    EXPECT_EQ(*store.find(Quantity<double>{"feature size"}), 0.25);
}

TEST(Quantities, CarriedValuesReachLaterPoses) {
    PoseQuantities first, later;
    first.keep(Quantity<int>{"carried"}, std::make_shared<const int>(7), PoseQuantities::Lifetime::CarriedToLaterPoses);
    first.keep(Quantity<int>{"own"}, std::make_shared<const int>(8));
    first.carry_to(later);
    ASSERT_NE(later.find(Quantity<int>{"carried"}), nullptr);
    EXPECT_EQ(*later.find(Quantity<int>{"carried"}), 7);
    EXPECT_EQ(later.find(Quantity<int>{"own"}), nullptr);
}

} // namespace
