// One sphere of the source body: centre and radius in mm, single precision because that is what
// Embree's sphere points (RTC_FORMAT_FLOAT4 x y z r) and the model file store.
#pragma once

namespace rayset::lightmodel {

struct Sphere {
    float x = 0, y = 0, z = 0, r = 0;
};

}  // namespace rayset::lightmodel
