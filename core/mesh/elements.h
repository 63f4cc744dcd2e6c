#pragma once
/// Strong ids for a mesh's elements (vertices, edges, faces, corners) and
/// containers indexed by them. An id is a typed index: a VertexId cannot
/// index per-face data, and no id converts silently to or from a plain
/// integer, so a stage that mixes up elements does not compile.
///
/// Ids count from 0 in the order the connectivity was built; the default id
/// is "no element" (MeshTopology::kNone converts to any id and compares
/// equal to it). A corner is one face's use of one of its vertices: corner
/// k (0-2) of face f has id 3f + k, so per-corner data lies face by face.

#include <compare>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <ostream>
#include <span>
#include <vector>

namespace snaxels {

/// "No element": converts to the invalid id of every kind.
struct NoElement {};

template <class Tag> class ElementId {
  public:
    constexpr ElementId() = default;
    constexpr ElementId(NoElement) {} // NOLINT: any id may be "none"
    constexpr explicit ElementId(std::int32_t index) : index_(index) {}
    constexpr explicit ElementId(std::size_t index) : index_(std::int32_t(index)) {}

    /// The id's position in its element array (-1 for none).
    constexpr std::int32_t index() const { return index_; }
    constexpr bool valid() const { return index_ >= 0; }
    constexpr ElementId& operator++() { return ++index_, *this; }

    friend constexpr bool operator==(const ElementId&, const ElementId&) = default;
    friend constexpr auto operator<=>(const ElementId&, const ElementId&) = default;

  private:
    std::int32_t index_ = -1;
};

/// An id prints as its index (in messages and test failures).
template <class Tag> std::ostream& operator<<(std::ostream& out, ElementId<Tag> id) { return out << id.index(); }

struct VertexTag;
struct EdgeTag;
struct FaceTag;
struct CornerTag;
using VertexId = ElementId<VertexTag>;
using EdgeId = ElementId<EdgeTag>;
using FaceId = ElementId<FaceTag>;
using CornerId = ElementId<CornerTag>;
// An id is its index and nothing more: arrays of ids have the layout of
// arrays of int32 (content hashes and ray-tracer buffers rely on it).
static_assert(sizeof(VertexId) == sizeof(std::int32_t) && alignof(VertexId) == alignof(std::int32_t));

/// Corner @p k (0-2) of face @p f.
constexpr CornerId corner_id(FaceId f, int k) { return CornerId(3 * f.index() + k); }
/// The face a corner belongs to, and its place (0-2) in it.
constexpr FaceId face_of(CornerId c) { return FaceId(c.index() / 3); }
constexpr int corner_place(CornerId c) { return c.index() % 3; }

/// Every id of one kind, from 0 to a count: `for (VertexId v : topology.vertices())`.
template <class Tag> class ElementRange {
  public:
    using Id = ElementId<Tag>;
    class iterator {
      public:
        using value_type = Id;
        using difference_type = std::ptrdiff_t;
        constexpr iterator() = default;
        constexpr explicit iterator(std::int32_t i) : i_(i) {}
        constexpr Id operator*() const { return Id(i_); }
        constexpr iterator& operator++() { return ++i_, *this; }
        constexpr iterator operator++(int) { return iterator(i_++); }
        friend constexpr bool operator==(const iterator&, const iterator&) = default;

      private:
        std::int32_t i_ = 0;
    };
    constexpr explicit ElementRange(std::size_t count) : count_(std::int32_t(count)) {}
    constexpr iterator begin() const { return iterator(0); }
    constexpr iterator end() const { return iterator(count_); }
    constexpr std::size_t size() const { return std::size_t(count_); }

  private:
    std::int32_t count_;
};

/// A view of per-element values (one per id, in id order), indexed by id.
template <class Tag, class T> class ElementSpan {
  public:
    using Id = ElementId<Tag>;
    constexpr ElementSpan() = default;
    constexpr explicit ElementSpan(std::span<T> values) : values_(values) {}

    constexpr T& operator[](Id id) const { return values_[std::size_t(id.index())]; }
    constexpr std::size_t size() const { return values_.size(); }
    constexpr bool empty() const { return values_.empty(); }
    constexpr auto begin() const { return values_.begin(); }
    constexpr auto end() const { return values_.end(); }
    constexpr T* data() const { return values_.data(); }
    /// The values as a plain span, for code that does not deal in elements
    /// (drawing, export, bounding boxes).
    constexpr std::span<T> values() const { return values_; }
    constexpr ElementRange<Tag> ids() const { return ElementRange<Tag>(values_.size()); }

  private:
    std::span<T> values_;
};

/// Per-element values owned: one per id, indexed by id, sized by the caller
/// to the element count (VertexData<double>(topology.n_vertices())).
template <class Tag, class T> class ElementData {
  public:
    using Id = ElementId<Tag>;
    ElementData() = default;
    explicit ElementData(std::size_t count, const T& value = T()) : values_(count, value) {}
    explicit ElementData(std::vector<T> values) : values_(std::move(values)) {}

    T& operator[](Id id) { return values_[std::size_t(id.index())]; }
    const T& operator[](Id id) const { return values_[std::size_t(id.index())]; }
    std::size_t size() const { return values_.size(); }
    bool empty() const { return values_.empty(); }
    void assign(std::size_t count, const T& value) { values_.assign(count, value); }
    void resize(std::size_t count) { values_.resize(count); }
    void resize(std::size_t count, const T& value) { values_.resize(count, value); }
    void clear() { values_.clear(); }
    void push_back(const T& value) { values_.push_back(value); }
    auto begin() { return values_.begin(); }
    auto end() { return values_.end(); }
    auto begin() const { return values_.begin(); }
    auto end() const { return values_.end(); }
    T* data() { return values_.data(); }
    const T* data() const { return values_.data(); }
    /// The values as a plain vector (in id order), for code that does not
    /// deal in elements.
    std::vector<T>& values() { return values_; }
    const std::vector<T>& values() const { return values_; }
    ElementRange<Tag> ids() const { return ElementRange<Tag>(values_.size()); }

    operator ElementSpan<Tag, const T>() const { return ElementSpan<Tag, const T>(values_); } // NOLINT

    friend bool operator==(const ElementData&, const ElementData&) = default;

  private:
    std::vector<T> values_;
};

template <class T> using VertexData = ElementData<VertexTag, T>;
template <class T> using EdgeData = ElementData<EdgeTag, T>;
template <class T> using FaceData = ElementData<FaceTag, T>;
template <class T> using CornerData = ElementData<CornerTag, T>;

} // namespace snaxels

template <class Tag> struct std::hash<snaxels::ElementId<Tag>> {
    std::size_t operator()(snaxels::ElementId<Tag> id) const noexcept { return std::hash<std::int32_t>()(id.index()); }
};
