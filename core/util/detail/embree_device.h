#pragma once
/// The one Embree device of the process (creating one starts a thread
/// pool): the ray scenes and the intersection curves' BVH collision share it.

#include <embree3/rtcore.h>

namespace snaxels::detail {

/// The process's Embree device; throws snaxels::Error when Embree cannot start.
RTCDevice embree_device();

} // namespace snaxels::detail
