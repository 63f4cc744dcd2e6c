// Strong element ids: kinds do not mix, ids do not pass for integers, and
// per-element containers, ranges and corners number the elements as the
// topology does.

#include <gtest/gtest.h>

#include <atomic>
#include <type_traits>

#include "snaxels/mesh/import.h"
#include "snaxels/mesh/topology.h"
#include "snaxels/util/detail/parallel.h"

using namespace snaxels;

// What the types are for: a face id is no vertex id, and no id converts to
// or from a plain integer without saying so.
static_assert(!std::is_convertible_v<VertexId, FaceId>);
static_assert(!std::is_convertible_v<FaceId, VertexId>);
static_assert(!std::is_convertible_v<EdgeId, VertexId>);
static_assert(!std::is_convertible_v<int, VertexId>);
static_assert(!std::is_convertible_v<VertexId, int>);
static_assert(!std::is_convertible_v<std::size_t, EdgeId>);
static_assert(std::is_convertible_v<NoElement, FaceId>); // "none" is every kind's
// A container of one kind takes that kind's ids only.
template <class Data, class Id> constexpr bool indexable = requires(Data& d, Id id) { d[id]; };
static_assert(indexable<VertexData<double>, VertexId>);
static_assert(!indexable<VertexData<double>, FaceId>);
static_assert(!indexable<VertexData<double>, std::size_t>);
static_assert(!indexable<ElementSpan<FaceTag, const int>, EdgeId>);

TEST(Elements, NoneIsInvalidAndOrdersFirst) {
    const VertexId none = MeshTopology::kNone;
    EXPECT_FALSE(none.valid());
    EXPECT_EQ(none, VertexId());
    EXPECT_TRUE(VertexId(0).valid());
    EXPECT_LT(none, VertexId(0));
    EXPECT_NE(VertexId(3), MeshTopology::kNone);
}

TEST(Elements, RangesAndContainersFollowTheTopology) {
    const MeshTopology topo = build_topology(load_mesh("proc:torus:400").mesh);
    std::size_t n = 0;
    VertexId last;
    for (const VertexId v : topo.vertices()) {
        EXPECT_EQ(v.index(), std::int32_t(n)) << "ids count from 0 in order";
        last = v, ++n;
    }
    EXPECT_EQ(n, topo.n_vertices());
    EXPECT_EQ(last, VertexId(topo.n_vertices() - 1));
    // A container sized to the faces holds one value per face id.
    FaceData<int> marks(topo.n_faces(), 0);
    for (const FaceId f : topo.faces()) marks[f] = f.index() * 2;
    EXPECT_EQ(marks.values().back(), 2 * std::int32_t(topo.n_faces() - 1));
    // Every corner's vertex is its face's vertex at its place.
    for (const CornerId c : topo.corners()) {
        const FaceId f = face_of(c);
        EXPECT_EQ(corner_id(f, corner_place(c)), c);
        EXPECT_EQ(topo.corner_vertex(c), topo.face_vertices()[f][std::size_t(corner_place(c))]);
    }
    EXPECT_EQ(topo.n_corners(), 3 * topo.n_faces());
}

TEST(Elements, CirculatorsAgreeWithTheFaceList) {
    // Each face at a vertex (faces_around) has the vertex at the corner it
    // names, each once, and they are all the faces the face list puts there.
    const MeshTopology topo = build_topology(load_mesh("proc:sphere:600").mesh);
    VertexData<int> faces_at(topo.n_vertices(), 0);
    for (const auto& f : topo.face_vertices())
        for (const VertexId v : f) ++faces_at[v];
    for (const VertexId v : topo.vertices()) {
        int count = 0;
        for (const auto [f, corner] : topo.faces_around(v)) {
            ASSERT_LT(corner, 3);
            EXPECT_EQ(topo.face_vertices()[f][std::size_t(corner)], v);
            ++count;
        }
        EXPECT_EQ(count, faces_at[v]) << "vertex " << v;
        for (const auto [w, e] : topo.ring_of(v)) EXPECT_EQ(topo.opposite(e, v), w);
    }
}

TEST(Elements, ParallelLoopVisitsEveryIdOnce) {
    const MeshTopology topo = build_topology(load_mesh("proc:sphere:4000").mesh);
    EdgeData<int> seen(topo.n_edges(), 0);
    parallel_for(topo.edges(), [&](EdgeId e) { ++std::atomic_ref<int>(seen[e]); }, 64);
    for (const EdgeId e : topo.edges()) ASSERT_EQ(seen[e], 1) << "edge " << e;
}
