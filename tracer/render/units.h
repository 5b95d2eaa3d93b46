// The renderer's units. Geometry stays in the scene's length unit (GlobalSettings::length_unit),
// so internally radiance is W/(unit^2 sr) and irradiance W/unit^2; the film converts to SI
// (W/(m^2 sr), W/m^2) on output. Intensities are W/sr and powers W in every unit.
#pragma once

namespace rayset::tracer {

struct SceneUnits {
    double metres_per_unit = 1e-3;
    // Multiplies an internal radiance or irradiance to give it per square metre.
    double per_square_metre() const { return 1 / (metres_per_unit * metres_per_unit); }
};

}  // namespace rayset::tracer
