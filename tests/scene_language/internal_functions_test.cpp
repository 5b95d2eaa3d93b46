// POV-Ray's internal functions (internal_functions.h) against POV-Ray itself, and their names
// and parameter counts against functions.inc.
#include "tracer/scene_language/internal_functions.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace rayset::tracer {
namespace {

struct Reference {
    const char* function;
    std::vector<double> args;  // x, y, z, P0, ...
    double value;
};

// The values come from POV-Ray 3.7.0.10's #debug output at 12 decimals (str(value, 0, 12)),
// produced by tests/scene_language/internal_functions_reference.sh, which prints these rows.
const Reference kReferences[] = {
    // extruded along z
    {"f_algbr_cyl1", {0.3, -0.4, 0.7, 1, 1.5, 0, 0, 0}, 0.097000000000},
    // |x|^3 for negative x
    {"f_algbr_cyl1", {-1.3, 0.2, 0.5, 1, 10, 0, 0, 0}, 0.547000000000},
    // swept around y: offset and angle
    {"f_algbr_cyl1", {0.9, 0.4, -0.8, 1, 1.5, 1, 0.3, 25}, 0.406597046632},
    // held at the field limit
    {"f_algbr_cyl1", {1.8, 0.3, 0, 2, 1.5, 0, 0, 0}, 1.500000000000},
    // a negative limit: -P1 wins
    {"f_algbr_cyl1", {0.3, -0.4, 0.7, 1, -2, 0, 0, 0}, 2.000000000000},
    {"f_algbr_cyl2", {0.5, 0.9, 0.1, -0.3, 5, 0, 0, 0}, -0.162570000000},
    {"f_algbr_cyl2", {0.4, 0.8, 0.6, 0.3, 5, 1, -0.2, -40}, -1.300835567494},
    // a negative limit: P1 wins
    {"f_algbr_cyl2", {0.3, -0.4, 0.7, 1, -2, 0, 0, 0}, -2.000000000000},
    {"f_algbr_cyl3", {0.6, 0.7, 0.2, -1, 3, 0, 0, 0}, -0.002000000000},
    {"f_algbr_cyl3", {0.6, 0.7, 0.2, -1, 3, 1, 0.1, 15}, 0.346989854495},
    // held at -P1
    {"f_algbr_cyl3", {1.6, 1.7, 0.2, -1, 3, 0, 0, 0}, 3.000000000000},
    {"f_algbr_cyl4", {0.5, 0.4, 0.3, -0.4, 5, 0, 0, 0}, 0.161640000000},
    {"f_algbr_cyl4", {0.5, 0.4, 0.3, -0.4, 5, 1, 0.25, 60}, 0.001708927842},
    {"f_bicorn", {0.4, 0.3, 0.2, -1, 1}, -0.032000000000},
    {"f_bicorn", {0.7, -0.5, 0.9, 0.5, 2.5}, -10.000000000000},
    // held at -10
    {"f_bicorn", {3, 2, 1, 1, 1}, -10.000000000000},
    {"f_bifolia", {0.4, 0.5, 0.3, -1, 3}, -0.125000000000},
    {"f_bifolia", {0.9, 0.2, -0.6, 2, 0.7}, -2.600600000000},
    {"f_blob", {0.1, 0.2, 0.3, 1.4, 1, 0.8, 1.2, 1}, -0.569371840000},
    // outside component 2
    {"f_blob", {-0.9, 0.4, 0.1, 1.4, 1, 0.8, 1.2, 1}, -0.749263360000},
    // outside both
    {"f_blob", {2.5, 0, 0, 1.4, 1, 0.8, 1.2, 1}, -0.000000000000},
    {"f_blob2", {0.3, 0.2, 0.1, 1, 5, 2, 1}, -0.127581633062},
    {"f_blob2", {1.2, -0.4, 0.3, 0.7, 2, -1.5, 0.25}, 0.852890343859},
    {"f_boy_surface", {0.3, 0.2, 0.4, -0.001, 0.01}, 0.000064216785},
    {"f_boy_surface", {0.25, -0.35, 0.6, 1, 0.5}, -7.176322970869},
    // held at -10
    {"f_boy_surface", {0.9, 0.8, 0.7, 1, 3}, -10.000000000000},
    {"f_cross_ellipsoids", {0.3, 0.4, 0.5, 0.05, 8, 8, 1}, -2.305016751026},
    {"f_cross_ellipsoids", {0.6, -0.2, 0.1, 2, 1.5, 1, 0}, -0.501576069066},
    // eccentricity 0: infinite ellipsoids
    {"f_cross_ellipsoids", {0.2, 0.7, -0.9, 0, 1, 1, 0}, -0.960789439152},
    {"f_crossed_trough", {1.2, 0.5, 0.9, -0.05}, -0.033320000000},
    {"f_crossed_trough", {0.7, -0.3, 1.1, 2}, 1.785800000000},
    {"f_cubic_saddle", {1.3, 0.4, -0.8, -0.5}, 1.466500000000},
    // held at +10
    {"f_cubic_saddle", {2.1, 0.2, 0.3, -1.5}, 10.000000000000},
    {"f_cushion", {0.4, 0.6, 0.3, -0.25}, -0.078375000000},
    {"f_cushion", {1.1, -0.7, 0.9, 1}, -0.542900000000},
    {"f_devils_curve", {0.5, 0.6, 0.2, -0.2}, -0.009100000000},
    {"f_devils_curve", {0.9, -0.3, 0.7, 1}, -1.412800000000},
    {"f_devils_curve_2d", {0.3, 0.2, 0.5, -1, 0.25, 0.3, 0, 0, 0}, 0.004475000000},
    {"f_devils_curve_2d", {0.3, 0.2, 0.5, -1, 0.25, 0.3, 1, 0.1, 30}, -0.010170009878},
    {"f_dupin_cyclid", {0.3, 0.2, 0.1, -0.05, 0.27, 0.04, 0.55, 0, 1}, 0.025217327091},
    {"f_dupin_cyclid", {0.6, -0.4, 0.5, 0.01, 1.2, 0.3, 0.5, 0.2, 0.8}, -0.009187156800},
    // the origin: -P5^8
    {"f_dupin_cyclid", {0, 0, 0, 1, 1, 0.3, 0.2, 0.1, 1.2}, -4.299816960000},
    {"f_ellipsoid", {0.5, 0.2, 0.3, 1.05, 3.3, 1.05}, 0.900249965287},
    {"f_ellipsoid", {-0.7, 0.4, 1.1, 0.5, 2, -1}, 1.404457190519},
    // far from z = 0: 1/z
    {"f_enneper", {0.5, 0.3, 0.6, 0.1}, 0.002681837037},
    {"f_enneper", {0.5, 0.3, -0.45, 1}, 0.036350960048},
    // |z| < 0.2: z taken as 0.2 below the line
    {"f_enneper", {0.5, 0.3, 0.1, 1}, 0.302939248285},
    // z = -0.2 is not below 0.2 in magnitude
    {"f_enneper", {0.5, 0.3, -0.2, 1}, 0.171637816187},
    // held at +10
    {"f_enneper", {1.9, 0.1, 0.05, -2}, -10.000000000000},
    {"f_flange_cover", {0.3, 0.4, 0.5, 0.01, 35, 1.5, 1.2}, 1.139172200479},
    {"f_flange_cover", {0.2, -0.1, 0.3, 0.5, 2, 1, 0}, -2.490511790340},
    {"f_folium_surface", {0.3, 0.2, 0.1, -0.02, 15, 15}, -0.016300000000},
    {"f_folium_surface", {-0.4, 0.5, 0.6, 1, 0.7, -1.2}, 1.554000000000},
    {"f_folium_surface_2d", {0.3, 0.2, 0.1, -0.01, 12, 20, 0, 0, 0}, 0.015940000000},
    {"f_folium_surface_2d", {0.3, 0.2, 0.1, -0.01, 12, 20, 1, 0.2, -30}, 0.007843462045},
    {"f_glob", {0.4, 0.3, 0.2, -1}, 0.112080000000},
    {"f_glob", {-1.3, 0.5, 0.1, 0.8}, -0.550732000000},
    {"f_heart", {0.3, 0.2, 0.4, -0.001}, -0.000241464000},
    {"f_heart", {0.5, -0.4, 0.7, 1}, 0.060080000000},
    {"f_helix1", {0.6, 0.2, 0.5, 1, 8, 0.3, 0.9, 0.6, 0.2, 0}, -0.123231847391},
    {"f_helix1", {0.9, 0.15, -0.2, 2, 2.5, 0.2, 1, 1.5, 1, 0}, 0.185180428389},
    // square cross section, rotated
    {"f_helix1", {-0.8, 0.3, 0.4, 3, 1.5, 0.25, 0.8, 1, 0, 30}, -0.163674450786},
    {"f_helix1", {1.2, -0.4, -0.3, 2.5, -1.2, 0.15, 1.1, 0.7, 2.6, -75}, 1.439558479126},
    // capped at the distance through the axis
    {"f_helix1", {0.1, 0, 0.05, 1, 1, 0.3, 1, 1, 1, 0}, 0.811803398875},
    // no helix (P0 = 0): the cap
    {"f_helix1", {0.3, 0.2, 0.1, 0, 1, 0.3, 1, 1, 1, 0}, 1.016227766017},
    {"f_helix2", {0.4, 0.2, 0.3, 0, 8, 0.35, 0.4, 0, 0.5, 0}, 0.059160849159},
    // the rotation has no effect
    {"f_helix2", {0.4, 0.2, 0.3, 0, 8, 0.35, 0.4, 0, 0.5, 60}, 0.059160849159},
    {"f_helix2", {-0.5, 0.7, 0.9, 3, -2, 0.3, 1.2, 5, 3, 0}, 2.883364600327},
    {"f_hex_x", {0.3, 0.2, 0.7, 1}, 0.323205080757},
    {"f_hex_x", {1.5, 0.9, -2, 1}, 0.836602540378},
    {"f_hex_x", {-3.1, 4.4, 0, 1}, 0.501923788647},
    {"f_hex_y", {0.3, 0.2, 0.7, 1}, 0.159807621135},
    {"f_hex_y", {1.5, 0.9, -2, 1}, 0.249038105677},
    {"f_hex_y", {-3.1, 4.4, 0, 1}, 0.100000000000},
    {"f_hunt_surface", {0.5, 0.4, 0.3, -0.0001}, -0.427273250000},
    {"f_hunt_surface", {1.1, 0.7, 0.2, 0.0005}, 1.982595152000},
    {"f_hyperbolic_torus", {0.6, 0.3, 0.4, -0.005, 1, 0.6}, 0.000324500000},
    {"f_hyperbolic_torus", {1.2, -0.5, 0.8, 0.5, 0.7, 0.2}, -0.341000000000},
    {"f_isect_ellipsoids", {0.3, 0.4, 0.5, 5, 1, 18, 1}, -1.117787174392},
    {"f_isect_ellipsoids", {0.6, -0.2, 0.1, 0.5, 1.5, 1, 0}, -0.561299863623},
    {"f_kampyle_of_eudoxus", {0.3, 0.2, 0.1, -0.001, 0.01, 2}, 0.000017636000},
    {"f_kampyle_of_eudoxus", {1.2, -0.4, 0.5, 0.5, 0.6, 1.5}, 1.544600000000},
    {"f_kampyle_of_eudoxus_2d", {0.3, 0.2, 0.1, -0.001, 0, 2, 0, 0, 0}, 0.000007600000},
    {"f_kampyle_of_eudoxus_2d", {0.3, 0.2, 0.1, -0.1, 0.4, 2, 1, 0, 90}, 0.022160000000},
    {"f_klein_bottle", {0.3, 0.2, 0.1, -0.0005}, -0.000649148000},
    {"f_klein_bottle", {0.9, -0.6, 0.4, 0.05}, -0.394490850000},
    {"f_kummer_surface_v1", {0.4, 0.5, 0.6, -0.01}, 0.002601000000},
    {"f_kummer_surface_v1", {1.3, 0.2, -0.9, 1}, -0.504900000000},
    {"f_kummer_surface_v2", {0.4, 0.5, 0.6, -0.0005, -0.3, -0.97, 0}, -0.000597636000},
    {"f_kummer_surface_v2", {0.7, -0.3, 0.9, 0.5, 0.4, 1.5, -2}, -0.804575000000},
    {"f_lemniscate_of_gerono", {0.5, 0.2, 0.1, -0.1}, -0.013750000000},
    {"f_lemniscate_of_gerono", {1.2, -0.3, 0.4, 1}, -0.883600000000},
    {"f_lemniscate_of_gerono_2d", {0.5, 0.2, 0.1, -0.1, 1, 1, 0, 2, -45}, -0.014750000000},
    {"f_lemniscate_of_gerono_2d", {0.5, 0.2, 0.1, -0.1, 1, 1, 1, 2, -45}, 0.128855692589},
    {"f_mesh1", {0.3, 0.02, 0.2, 0.125, 0.125, 0.1, 0.01, 0.1}, 0.005278202679},
    {"f_mesh1", {0.7, 0.1, -0.45, 1, 1.5, 1, 0.2, 2}, 0.302048009567},
    // the nearer of two threads that cross
    {"f_mesh1", {1.4, -0.3, 2.1, 0.6, 0.8, 1.5, 0.4, 0.7}, 0.436560403408},
    {"f_mitre", {0.3, 0.2, 0.1, -0.5}, 0.006200000000},
    {"f_mitre", {0.6, -0.9, 0.4, 1}, -1.890900000000},
    {"f_nodal_cubic", {0.3, 0.7, 0.9, -0.005}, -0.013540000000},
    {"f_nodal_cubic", {1.1, -0.4, 0.8, 1}, -2.368000000000},
    {"f_odd", {0.4, 0.6, 0.3, -0.25}, -0.078375000000},
    {"f_odd", {-0.8, 0.5, 1.2, 1}, -0.238100000000},
    {"f_ovals_of_cassini", {0.3, 0.2, 0.1, -0.1, 0.4, 0.18, 6}, -0.003840000000},
    {"f_ovals_of_cassini", {0.6, -0.4, 0.8, 1, 0.7, 0.5, 2}, -1.492500000000},
    {"f_paraboloid", {0.3, 0.4, 0.5, -1}, -0.060000000000},
    {"f_paraboloid", {1.7, -0.4, 0.9, 3}, -10.000000000000},
    {"f_parabolic_torus", {0.3, 0.2, 0.1, -0.1, 0.4, 0.5}, 0.000950000000},
    {"f_parabolic_torus", {0.9, -0.6, 0.4, 1, 1.1, 0.6}, -0.977700000000},
    {"f_ph", {0.3, 0.4, 0.5}, 0.969532110116},
    {"f_ph", {-0.2, -0.9, 0.1}, 2.898071463825},
    // the origin
    {"f_ph", {0, 0, 0}, 0.000000000000},
    {"f_pillow", {0.4, 0.5, 0.6, 1}, -0.552300000000},
    {"f_pillow", {1.2, -0.3, 0.8, -0.5}, -0.160650000000},
    {"f_piriform", {0.4, 0.3, 0.2, 0.7}, 0.064120000000},
    {"f_piriform", {1.3, -0.5, 0.4, -1}, -1.069100000000},
    {"f_piriform_2d", {0.4, 0.3, 0.2, -1, 1, -1, 0.9, 0, 0, 0}, 0.058896000000},
    {"f_piriform_2d", {0.4, 0.3, 0.2, -1, 1, -1, 0.9, 1, 0, -90}, 0.184691000000},
    {"f_poly4", {0.3, 0.2, 0.4, 0, 1, -1, 0, 0}, 0.340000000000},
    {"f_poly4", {0.6, 0.9, -0.2, 0.5, -0.3, 0.7, 1.2, -0.8}, -0.514464467966},
    // the polynomial held at -5
    {"f_poly4", {0.3, 1.5, 0.4, -3, -2, 0, 0, 0}, 5.500000000000},
    {"f_polytubes", {0.3, 0.2, 0.4, 8, -1, -0.01, -0.02, 0.1, -0.25}, 0.512328398153},
    {"f_polytubes", {0.6, -0.5, -0.7, 3, 0.5, 0.2, 0, 0, 0}, 0.560631613614},
    // a negative radius: the opposite tubes
    {"f_polytubes", {-0.3, 0.1, -0.2, 7, -1, 0.5, 0, 0, 0}, 0.591548755630},
    // 2 tubes, 144 degrees apart
    {"f_polytubes", {0.2, 0, -0.9, 2.5, 0.5, 0, 0, 0, 0}, 0.504309086379},
    // no tube
    {"f_polytubes", {0.3, 0.2, 0.4, 0.9, 1, 0, 0, 0, 0}, 10000.000000000000},
    // at most 10000
    {"f_polytubes", {30000, 0, 0, 1, 0, 0, 0, 0, 0}, 10000.000000000000},
    {"f_quantum", {0.3, 0.4, 0.5, 0}, 1.199750699463},
    {"f_quantum", {-1.2, 2.1, 0.7, 5}, -1.445601059069},
    {"f_quantum", {0, 0, 0, 0}, 1.200000000000},
    {"f_quartic_paraboloid", {0.4, 0.5, 0.6, -0.01}, -0.003448000000},
    {"f_quartic_paraboloid", {1.1, -0.3, 0.7, 1}, -2.004200000000},
    {"f_quartic_saddle", {0.4, 0.5, 0.6, 0.05}, 0.030200000000},
    {"f_quartic_saddle", {1.1, -0.3, 0.7, -1}, 1.524000000000},
    {"f_quartic_cylinder", {0.4, 0.5, 0.6, -1, 0.8, 0.2}, 0.125200000000},
    {"f_quartic_cylinder", {0.9, -0.3, 0.2, 0.5, 1.2, 0.7}, 0.106300000000},
    {"f_r", {0.3, 0.4, 0.5}, 0.707106781187},
    {"f_r", {-1.2, 0.7, 2.3}, 2.687005768509},
    {"f_rounded_box", {0.9, 0.95, 0.5, 0.3, 1, 1, 1}, 0.020155211872},
    {"f_rounded_box", {1.4, 0.2, -0.6, 0.2, 1, 0.5, 1.5}, 0.399999000000},
    // inside: -P0 - 1e-6
    {"f_rounded_box", {0.1, 0.2, 0.3, 0.3, 1, 1, 1}, -0.300001000000},
    {"f_sphere", {1, 2, 3, 0.5}, 3.241657386774},
    {"f_sphere", {0.2, -0.3, 0.1, 1}, -0.625834261323},
    {"f_spikes", {0.3, 0.4, 0.5, 0.04, 5.6, -4, 0.1, 1}, -0.845208823907},
    {"f_spikes", {0.6, -0.2, 0.3, 0.5, 2, 1.5, 0.8, 0.7}, 1.654388082630},
    {"f_spikes_2d", {0.3, 0.2, 0.1, 0.7, 15, 15, 2.2}, 0.208376509429},
    {"f_spikes_2d", {-0.6, 0.5, 0.9, 1.3, 2, -3, 0.4}, 0.766706857069},
    {"f_spiral", {0.3, 0.01, 0.2, 0.2, 0.04, 1, 0, 0, 1}, 0.039900083263},
    {"f_spiral", {-0.45, -0.03, 0.6, 0.3, 0.05, 1, 0, 0, 0}, 0.055724914705},
    // capped at the distance to the origin
    {"f_spiral", {0.2, 0.1, -0.1, 0.25, 0.04, 1, 0, 0, 3.6}, 0.204948974278},
    // outside the sphere of radius P2
    {"f_spiral", {1.1, 0.2, 0.5, 0.2, 0.04, 1, 0, 0, 1}, 0.224744871392},
    // on the axis: 1e-6 from it
    {"f_spiral", {0, 0, 0, 0.2, 0, 1, 0, 0, 1}, 0.000001000000},
    // no spacing: the sphere alone
    {"f_spiral", {0.3, 0.1, 0.2, 0, 0.04, 1, 0, 0, 1}, -0.625834261323},
    {"f_steiners_roman", {0.3, 0.4, 0.5, -1}, 0.136900000000},
    {"f_steiners_roman", {-0.7, 0.2, 0.9, 2}, -0.645800000000},
    {"f_strophoid", {0.3, 0.2, 0.4, -0.2, 2, 0.5, 0.9}, -0.025534000000},
    {"f_strophoid", {-0.5, 0.6, 0.1, 1, -1, -0.3, 1.4}, -0.809000000000},
    {"f_strophoid_2d", {0.3, 0.2, 0.4, 0.02, -8, 0.8, 0.3, 0, 0, 0}, -0.001647400000},
    {"f_strophoid_2d", {0.3, 0.2, 0.4, 0.02, -8, 0.8, 0.3, 1, -0.2, 20}, -0.005402913465},
    {"f_superellipsoid", {0.3, 0.4, 0.5, 0.3, 0.5}, 0.451829872597},
    {"f_superellipsoid", {-0.6, 0.2, -0.1, 2, 0.7}, 0.199264588746},
    {"f_superellipsoid", {0, 0, 0.4, 1.5, 2.5}, 0.600000000000},
    {"f_th", {0.3, 0.4, 0.5}, 0.540419500271},
    {"f_th", {-0.5, 0.1, -0.2}, -1.951302703907},
    // the origin
    {"f_th", {0, 0, 0}, 0.000000000000},
    {"f_torus", {1, 2, 3, 0.5, 0.2}, 3.129823169454},
    {"f_torus", {0.6, 0.1, 0.5, 0.8, 0.2}, -0.098215660070},
    {"f_torus2", {0.3, 0.2, 0.4, -1, 0.4, 0.07}, 0.038114010000},
    {"f_torus2", {0.9, -0.3, 0.5, 0.5, 1, 0.3}, -0.001800000000},
    {"f_torus_gumdrop", {0.4, 0.3, 0.2, -0.01}, 0.117236000000},
    {"f_torus_gumdrop", {1.1, -0.5, 0.6, 0.5}, -0.246250000000},
    {"f_umbrella", {0.4, 0.6, 0.8, -0.2}, -0.044800000000},
    {"f_umbrella", {-1.3, 0.9, 1.5, 1}, 0.335000000000},
    {"f_witch_of_agnesi", {0.3, 0.2, 0.1, -0.09, 0.02}, 0.000360000000},
    {"f_witch_of_agnesi", {0.7, -0.4, 0.5, 1, 0.6}, 1.136000000000},
    {"f_witch_of_agnesi_2d", {0.3, 0.2, 0.1, -0.2, 0.2, 0.08, 0, 0, 0}, -0.010800000000},
    {"f_witch_of_agnesi_2d", {0.3, 0.2, 0.1, -0.2, 0.2, 0.08, 1, 0.3, -15}, -0.014316219453},
};

// The fractal noises (POV-Ray's noise agrees in distribution only: f_noise3d and
// f_noise_generator are checked that way in povray_differential_test.cpp), and those whose
// formula is not established (f_comma, f_helical_torus, the unnamed internal(77)).
const char* const kNotImplemented[] = {"f_comma", "f_helical_torus", "f_hetero_mf", "f_ridge",
                                       "f_ridged_mf"};

constexpr int kLastInternal = 78;

int number_of(const std::string& name) {
    for (int n = 0; n <= kLastInternal; ++n)
        if (name == internal_function_name(n)) return n;
    return -1;
}

std::string call_text(const Reference& r) {
    std::ostringstream text;
    text << r.function << '(';
    for (size_t i = 0; i < r.args.size(); ++i) text << (i ? ", " : "") << r.args[i];
    text << ')';
    return text.str();
}

TEST(InternalFunctions, MatchPovRay) {
    for (const Reference& r : kReferences) {
        SCOPED_TRACE(call_text(r));
        const int number = number_of(r.function);
        ASSERT_GE(number, 0);
        ASSERT_EQ(static_cast<int>(r.args.size()), internal_function_arity(number));
        double value = 0;
        ASSERT_TRUE(evaluate_internal_function(number, r.args.data(), value));
        // 1e-9 relative; the 1e-12 absolute part covers POV-Ray's rounding to 12 decimals.
        EXPECT_NEAR(value, r.value, 1e-9 * std::fabs(r.value) + 1e-12);
    }
}

TEST(InternalFunctions, EveryImplementedFunctionIsChecked) {
    // The noises are checked in distribution (povray_differential_test.cpp).
    std::set<std::string> checked = {"f_noise3d", "f_noise_generator"};
    for (const Reference& r : kReferences) checked.insert(r.function);
    for (int n = 0; n <= kLastInternal; ++n) {
        const std::vector<double> args(internal_function_arity(n), 0.5);
        double value = 0;
        if (evaluate_internal_function(n, args.data(), value)) {
            EXPECT_EQ(checked.count(internal_function_name(n)), 1u) << internal_function_name(n);
        }
    }
}

TEST(InternalFunctions, UnsupportedOnesSayNo) {
    for (const char* name : kNotImplemented) {
        const int number = number_of(name);
        ASSERT_GE(number, 0) << name;
        const std::vector<double> args(internal_function_arity(number), 0.5);
        double value = 0;
        EXPECT_FALSE(evaluate_internal_function(number, args.data(), value)) << name;
    }
}

TEST(InternalFunctions, NumbersOutsidePovRays) {
    for (int n : {-1, kLastInternal + 1, 1000}) {
        EXPECT_EQ(internal_function_arity(n), -1) << n;
        EXPECT_STREQ(internal_function_name(n), "") << n;
        const double args[16] = {};
        double value = 0;
        EXPECT_FALSE(evaluate_internal_function(n, args, value)) << n;
    }
    // POV-Ray 3.7 accepts internal(77) with three parameters; functions.inc gives it no name.
    EXPECT_EQ(internal_function_arity(77), 3);
    EXPECT_STREQ(internal_function_name(77), "");
}

// functions.inc: `#declare f_xxx = function { internal(N) }`, then comments such as "Five
// extra parameters required" (no count for f_noise3d: x, y, z only). The file's own spellings
// ("Tree extra parameters", "Four parameters required") are read as meant.
struct Declared {
    std::string name;
    int number;
    int parameters;
};

int count_word(std::string word) {
    for (char& c : word) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    static const std::map<std::string, int> kWords = {
        {"no", 0},   {"one", 1}, {"two", 2},   {"three", 3}, {"tree", 3}, {"four", 4},
        {"five", 5}, {"six", 6}, {"seven", 7}, {"eight", 8}, {"nine", 9}, {"ten", 10}};
    const auto it = kWords.find(word);
    return it == kWords.end() ? -1 : it->second;
}

std::vector<Declared> read_functions_inc(std::istream& in) {
    static const std::regex declaration(
        R"(#declare\s+(\w+)\s*=\s*function\s*\{\s*internal\s*\(\s*(\d+)\s*\)\s*\})");
    static const std::regex count(R"((\w+)\s+(?:extra\s+)?para\w*\s+required)", std::regex::icase);
    std::vector<Declared> declared;
    bool counted = true;
    std::string line;
    while (std::getline(in, line)) {
        std::smatch m;
        if (std::regex_search(line, m, declaration)) {
            declared.push_back({m[1], std::stoi(m[2]), 3});
            counted = false;
        } else if (line.find("#declare") != std::string::npos ||
                   line.find("#macro") != std::string::npos) {
            counted = true;
        } else if (!counted && std::regex_search(line, m, count)) {
            declared.back().parameters = 3 + count_word(m[1]);
            counted = true;
        }
    }
    return declared;
}

TEST(InternalFunctions, NamesAndParametersOfFunctionsInc) {
    std::ifstream in("/usr/share/povray-3.7/include/functions.inc");
    if (!in) GTEST_SKIP() << "POV-Ray 3.7's functions.inc is not installed";
    const std::vector<Declared> declared = read_functions_inc(in);
    ASSERT_EQ(declared.size(), 78u);  // internal(0) to internal(78), but for 77
    for (const Declared& d : declared) {
        SCOPED_TRACE(d.name);
        EXPECT_STREQ(internal_function_name(d.number), d.name.c_str());
        EXPECT_EQ(internal_function_arity(d.number), d.parameters);
    }
}

}  // namespace
}  // namespace rayset::tracer
