#!/bin/bash
# Regenerates the reference values of internal_functions_test.cpp: evaluates each case below
# with POV-Ray (`povray`, 3.7.0.10 for the values in the test) and prints the test's table rows,
# each value as POV-Ray's #debug prints it with str(value, 0, 12).
#
#   tests/scene_language/internal_functions_reference.sh > rows.inc
#
# A case is a function of functions.inc, its arguments (x, y, z, P0, ...) and an optional
# comment after '#', printed above the row. Arguments are short decimals so that POV-Ray
# and the C++ compiler read the same doubles.
set -euo pipefail

read -r -d '' CASES <<'EOF' || true
f_algbr_cyl1 0.3 -0.4 0.7 1 1.5 0 0 0        # extruded along z
f_algbr_cyl1 -1.3 0.2 0.5 1 10 0 0 0         # |x|^3 for negative x
f_algbr_cyl1 0.9 0.4 -0.8 1 1.5 1 0.3 25     # swept around y: offset and angle
f_algbr_cyl1 1.8 0.3 0 2 1.5 0 0 0           # held at the field limit
f_algbr_cyl1 0.3 -0.4 0.7 1 -2 0 0 0         # a negative limit: -P1 wins
f_algbr_cyl2 0.5 0.9 0.1 -0.3 5 0 0 0
f_algbr_cyl2 0.4 0.8 0.6 0.3 5 1 -0.2 -40
f_algbr_cyl2 0.3 -0.4 0.7 1 -2 0 0 0         # a negative limit: P1 wins
f_algbr_cyl3 0.6 0.7 0.2 -1 3 0 0 0
f_algbr_cyl3 0.6 0.7 0.2 -1 3 1 0.1 15
f_algbr_cyl3 1.6 1.7 0.2 -1 3 0 0 0          # held at -P1
f_algbr_cyl4 0.5 0.4 0.3 -0.4 5 0 0 0
f_algbr_cyl4 0.5 0.4 0.3 -0.4 5 1 0.25 60
f_bicorn 0.4 0.3 0.2 -1 1
f_bicorn 0.7 -0.5 0.9 0.5 2.5
f_bicorn 3 2 1 1 1                           # held at -10
f_bifolia 0.4 0.5 0.3 -1 3
f_bifolia 0.9 0.2 -0.6 2 0.7
f_blob 0.1 0.2 0.3 1.4 1 0.8 1.2 1
f_blob -0.9 0.4 0.1 1.4 1 0.8 1.2 1          # outside component 2
f_blob 2.5 0 0 1.4 1 0.8 1.2 1               # outside both
f_blob2 0.3 0.2 0.1 1 5 2 1
f_blob2 1.2 -0.4 0.3 0.7 2 -1.5 0.25
f_boy_surface 0.3 0.2 0.4 -0.001 0.01
f_boy_surface 0.25 -0.35 0.6 1 0.5
f_boy_surface 0.9 0.8 0.7 1 3                # held at -10
f_cross_ellipsoids 0.3 0.4 0.5 0.05 8 8 1
f_cross_ellipsoids 0.6 -0.2 0.1 2 1.5 1 0
f_cross_ellipsoids 0.2 0.7 -0.9 0 1 1 0      # eccentricity 0: infinite ellipsoids
f_crossed_trough 1.2 0.5 0.9 -0.05
f_crossed_trough 0.7 -0.3 1.1 2
f_cubic_saddle 1.3 0.4 -0.8 -0.5
f_cubic_saddle 2.1 0.2 0.3 -1.5              # held at +10
f_cushion 0.4 0.6 0.3 -0.25
f_cushion 1.1 -0.7 0.9 1
f_devils_curve 0.5 0.6 0.2 -0.2
f_devils_curve 0.9 -0.3 0.7 1
f_devils_curve_2d 0.3 0.2 0.5 -1 0.25 0.3 0 0 0
f_devils_curve_2d 0.3 0.2 0.5 -1 0.25 0.3 1 0.1 30
f_dupin_cyclid 0.3 0.2 0.1 -0.05 0.27 0.04 0.55 0 1
f_dupin_cyclid 0.6 -0.4 0.5 0.01 1.2 0.3 0.5 0.2 0.8
f_dupin_cyclid 0 0 0 1 1 0.3 0.2 0.1 1.2     # the origin: -P5^8
f_ellipsoid 0.5 0.2 0.3 1.05 3.3 1.05
f_ellipsoid -0.7 0.4 1.1 0.5 2 -1
f_enneper 0.5 0.3 0.6 0.1                    # far from z = 0: 1/z
f_enneper 0.5 0.3 -0.45 1
f_enneper 0.5 0.3 0.1 1                      # |z| < 0.2: z taken as 0.2 below the line
f_enneper 0.5 0.3 -0.2 1                     # z = -0.2 is not below 0.2 in magnitude
f_enneper 1.9 0.1 0.05 -2                    # held at +10
f_flange_cover 0.3 0.4 0.5 0.01 35 1.5 1.2
f_flange_cover 0.2 -0.1 0.3 0.5 2 1 0
f_folium_surface 0.3 0.2 0.1 -0.02 15 15
f_folium_surface -0.4 0.5 0.6 1 0.7 -1.2
f_folium_surface_2d 0.3 0.2 0.1 -0.01 12 20 0 0 0
f_folium_surface_2d 0.3 0.2 0.1 -0.01 12 20 1 0.2 -30
f_glob 0.4 0.3 0.2 -1
f_glob -1.3 0.5 0.1 0.8
f_heart 0.3 0.2 0.4 -0.001
f_heart 0.5 -0.4 0.7 1
f_helix1 0.6 0.2 0.5 1 8 0.3 0.9 0.6 0.2 0
f_helix1 0.9 0.15 -0.2 2 2.5 0.2 1 1.5 1 0
f_helix1 -0.8 0.3 0.4 3 1.5 0.25 0.8 1 0 30   # square cross section, rotated
f_helix1 1.2 -0.4 -0.3 2.5 -1.2 0.15 1.1 0.7 2.6 -75
f_helix1 0.1 0 0.05 1 1 0.3 1 1 1 0          # capped at the distance through the axis
f_helix1 0.3 0.2 0.1 0 1 0.3 1 1 1 0         # no helix (P0 = 0): the cap
f_helix2 0.4 0.2 0.3 0 8 0.35 0.4 0 0.5 0
f_helix2 0.4 0.2 0.3 0 8 0.35 0.4 0 0.5 60   # the rotation has no effect
f_helix2 -0.5 0.7 0.9 3 -2 0.3 1.2 5 3 0
f_hex_x 0.3 0.2 0.7 1
f_hex_x 1.5 0.9 -2 1
f_hex_x -3.1 4.4 0 1
f_hex_y 0.3 0.2 0.7 1
f_hex_y 1.5 0.9 -2 1
f_hex_y -3.1 4.4 0 1
f_hunt_surface 0.5 0.4 0.3 -0.0001
f_hunt_surface 1.1 0.7 0.2 0.0005
f_hyperbolic_torus 0.6 0.3 0.4 -0.005 1 0.6
f_hyperbolic_torus 1.2 -0.5 0.8 0.5 0.7 0.2
f_isect_ellipsoids 0.3 0.4 0.5 5 1 18 1
f_isect_ellipsoids 0.6 -0.2 0.1 0.5 1.5 1 0
f_kampyle_of_eudoxus 0.3 0.2 0.1 -0.001 0.01 2
f_kampyle_of_eudoxus 1.2 -0.4 0.5 0.5 0.6 1.5
f_kampyle_of_eudoxus_2d 0.3 0.2 0.1 -0.001 0 2 0 0 0
f_kampyle_of_eudoxus_2d 0.3 0.2 0.1 -0.1 0.4 2 1 0 90
f_klein_bottle 0.3 0.2 0.1 -0.0005
f_klein_bottle 0.9 -0.6 0.4 0.05
f_kummer_surface_v1 0.4 0.5 0.6 -0.01
f_kummer_surface_v1 1.3 0.2 -0.9 1
f_kummer_surface_v2 0.4 0.5 0.6 -0.0005 -0.3 -0.97 0
f_kummer_surface_v2 0.7 -0.3 0.9 0.5 0.4 1.5 -2
f_lemniscate_of_gerono 0.5 0.2 0.1 -0.1
f_lemniscate_of_gerono 1.2 -0.3 0.4 1
f_lemniscate_of_gerono_2d 0.5 0.2 0.1 -0.1 1 1 0 2 -45
f_lemniscate_of_gerono_2d 0.5 0.2 0.1 -0.1 1 1 1 2 -45
f_mesh1 0.3 0.02 0.2 0.125 0.125 0.1 0.01 0.1
f_mesh1 0.7 0.1 -0.45 1 1.5 1 0.2 2
f_mesh1 1.4 -0.3 2.1 0.6 0.8 1.5 0.4 0.7      # the nearer of two threads that cross
f_mitre 0.3 0.2 0.1 -0.5
f_mitre 0.6 -0.9 0.4 1
f_nodal_cubic 0.3 0.7 0.9 -0.005
f_nodal_cubic 1.1 -0.4 0.8 1
f_odd 0.4 0.6 0.3 -0.25
f_odd -0.8 0.5 1.2 1
f_ovals_of_cassini 0.3 0.2 0.1 -0.1 0.4 0.18 6
f_ovals_of_cassini 0.6 -0.4 0.8 1 0.7 0.5 2
f_paraboloid 0.3 0.4 0.5 -1
f_paraboloid 1.7 -0.4 0.9 3
f_parabolic_torus 0.3 0.2 0.1 -0.1 0.4 0.5
f_parabolic_torus 0.9 -0.6 0.4 1 1.1 0.6
f_ph 0.3 0.4 0.5
f_ph -0.2 -0.9 0.1
f_ph 0 0 0                                   # the origin
f_pillow 0.4 0.5 0.6 1
f_pillow 1.2 -0.3 0.8 -0.5
f_piriform 0.4 0.3 0.2 0.7
f_piriform 1.3 -0.5 0.4 -1
f_piriform_2d 0.4 0.3 0.2 -1 1 -1 0.9 0 0 0
f_piriform_2d 0.4 0.3 0.2 -1 1 -1 0.9 1 0 -90
f_poly4 0.3 0.2 0.4 0 1 -1 0 0
f_poly4 0.6 0.9 -0.2 0.5 -0.3 0.7 1.2 -0.8
f_poly4 0.3 1.5 0.4 -3 -2 0 0 0             # the polynomial held at -5
f_polytubes 0.3 0.2 0.4 8 -1 -0.01 -0.02 0.1 -0.25
f_polytubes 0.6 -0.5 -0.7 3 0.5 0.2 0 0 0
f_polytubes -0.3 0.1 -0.2 7 -1 0.5 0 0 0     # a negative radius: the opposite tubes
f_polytubes 0.2 0 -0.9 2.5 0.5 0 0 0 0       # 2 tubes, 144 degrees apart
f_polytubes 0.3 0.2 0.4 0.9 1 0 0 0 0        # no tube
f_polytubes 30000 0 0 1 0 0 0 0 0            # at most 10000
f_quantum 0.3 0.4 0.5 0
f_quantum -1.2 2.1 0.7 5
f_quantum 0 0 0 0
f_quartic_paraboloid 0.4 0.5 0.6 -0.01
f_quartic_paraboloid 1.1 -0.3 0.7 1
f_quartic_saddle 0.4 0.5 0.6 0.05
f_quartic_saddle 1.1 -0.3 0.7 -1
f_quartic_cylinder 0.4 0.5 0.6 -1 0.8 0.2
f_quartic_cylinder 0.9 -0.3 0.2 0.5 1.2 0.7
f_r 0.3 0.4 0.5
f_r -1.2 0.7 2.3
f_rounded_box 0.9 0.95 0.5 0.3 1 1 1
f_rounded_box 1.4 0.2 -0.6 0.2 1 0.5 1.5
f_rounded_box 0.1 0.2 0.3 0.3 1 1 1          # inside: -P0 - 1e-6
f_sphere 1 2 3 0.5
f_sphere 0.2 -0.3 0.1 1
f_spikes 0.3 0.4 0.5 0.04 5.6 -4 0.1 1
f_spikes 0.6 -0.2 0.3 0.5 2 1.5 0.8 0.7
f_spikes_2d 0.3 0.2 0.1 0.7 15 15 2.2
f_spikes_2d -0.6 0.5 0.9 1.3 2 -3 0.4
f_spiral 0.3 0.01 0.2 0.2 0.04 1 0 0 1
f_spiral -0.45 -0.03 0.6 0.3 0.05 1 0 0 0
f_spiral 0.2 0.1 -0.1 0.25 0.04 1 0 0 3.6   # capped at the distance to the origin
f_spiral 1.1 0.2 0.5 0.2 0.04 1 0 0 1        # outside the sphere of radius P2
f_spiral 0 0 0 0.2 0 1 0 0 1                 # on the axis: 1e-6 from it
f_spiral 0.3 0.1 0.2 0 0.04 1 0 0 1          # no spacing: the sphere alone
f_steiners_roman 0.3 0.4 0.5 -1
f_steiners_roman -0.7 0.2 0.9 2
f_strophoid 0.3 0.2 0.4 -0.2 2 0.5 0.9
f_strophoid -0.5 0.6 0.1 1 -1 -0.3 1.4
f_strophoid_2d 0.3 0.2 0.4 0.02 -8 0.8 0.3 0 0 0
f_strophoid_2d 0.3 0.2 0.4 0.02 -8 0.8 0.3 1 -0.2 20
f_superellipsoid 0.3 0.4 0.5 0.3 0.5
f_superellipsoid -0.6 0.2 -0.1 2 0.7
f_superellipsoid 0 0 0.4 1.5 2.5
f_th 0.3 0.4 0.5
f_th -0.5 0.1 -0.2
f_th 0 0 0                                   # the origin
f_torus 1 2 3 0.5 0.2
f_torus 0.6 0.1 0.5 0.8 0.2
f_torus2 0.3 0.2 0.4 -1 0.4 0.07
f_torus2 0.9 -0.3 0.5 0.5 1 0.3
f_torus_gumdrop 0.4 0.3 0.2 -0.01
f_torus_gumdrop 1.1 -0.5 0.6 0.5
f_umbrella 0.4 0.6 0.8 -0.2
f_umbrella -1.3 0.9 1.5 1
f_witch_of_agnesi 0.3 0.2 0.1 -0.09 0.02
f_witch_of_agnesi 0.7 -0.4 0.5 1 0.6
f_witch_of_agnesi_2d 0.3 0.2 0.1 -0.2 0.2 0.08 0 0 0
f_witch_of_agnesi_2d 0.3 0.2 0.1 -0.2 0.2 0.08 1 0.3 -15
EOF

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Each case becomes `#declare V = f(...);` and a short #debug line (POV-Ray wraps lines of 80
# characters and more).
{
    echo '#version 3.7;'
    echo '#include "functions.inc"'
    while read -r name args; do
        args=${args%%#*}
        echo "#declare V = $name($(echo $args | sed 's/ /, /g'));"
        echo '#debug concat("= ", str(V, 0, 12), "\n")'
    done <<<"$CASES"
} >"$work/cases.pov"

(cd "$work" && povray +Icases.pov +W1 +H1 -D +Oout.png +GDdebug.txt -GR -GS >povray.log 2>&1) || {
    cat "$work/povray.log" >&2
    exit 1
}

grep '^= ' "$work/debug.txt" | cut -c3- >"$work/values.txt"
paste <(echo "$CASES") "$work/values.txt" | while IFS=$'\t' read -r line value; do
    read -r name args <<<"${line%%#*}"
    [[ $line == *'#'* ]] && echo "    // $(echo "${line#*#}" | sed 's/^ *//')"
    echo "    {\"$name\", {$(echo $args | sed 's/ /, /g')}, $value},"
done
