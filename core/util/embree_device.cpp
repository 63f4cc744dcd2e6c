#include "snaxels/util/detail/embree_device.h"

#include "snaxels/error.h"

namespace snaxels::detail {

RTCDevice embree_device() {
    static const RTCDevice device = rtcNewDevice(nullptr);
    if (!device) throw Error("cannot start the ray tracer (Embree device)");
    return device;
}

} // namespace snaxels::detail
