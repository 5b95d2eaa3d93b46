// The paper's scene (its Figures 1, 4-7): a closed box lit by a cluster of 39 LED chips that
// hangs on the left wall, in view. The cluster is the ray file scripts/example.sh synthesises
// (`rayconv synth cluster`: rings of 1 + 6 + 12 + 20 square chips of 1 mm, red 630 nm, green
// 530 nm and blue 460 nm, 1 W in all); raytrace builds its light model at load (name a .vdb
// made by `raymodel build` instead to skip that), or with --naive-sources emits its rays.
// Render it as scripts/example.sh does:
//   raytrace examples/led_box.pov +Lout/example +W640 +H480 --time 90 -o out/example/led_box.exr
//   raytrace examples/led_box.pov +Lout/example +W640 +H480 --time 90 --naive-sources -o out/example/naive.exr
// Units: millimetres. The box is 120 mm wide, 100 mm high and 200 mm deep.
#version 3.7;

global_settings {
    length_unit "mm"
    integrator "bidirectional"
}

camera {
    location <30, 5, -95>
    look_at <-20, -5, 60>
    angle 75
}

#declare White = texture { pigment { rgb 0.6 } finish { diffuse 1 ambient 0 } }

// The box: the camera is inside it, every wall faces in.
box { <-60, -50, -100>, <60, 50, 100> texture { White } }

// A glossy grey block and a mirror ball on the floor: the cluster appears in the ball
// through a specular chain, and both cast shadows of its many small chips.
box { <-10, -50, 20>, <30, -20, 50> rotate <0, 25, 0>
      texture { pigment { rgb <0.7, 0.7, 0.75> } finish { diffuse 0.7 specular 0.3 roughness 0.05 ambient 0 } } }
sphere { <-25, -35, 55>, 15 texture { pigment { rgb 0 } finish { diffuse 0 reflection 0.9 ambient 0 } } }

// The cluster on the left wall, turned 20 degrees toward the camera. Its chips lie in the
// model's z = 0 plane and emit toward +z: rotate y by 110 points +z at (0.94, 0, -0.34).
ray_source { "cluster.tm25ray" rotate <0, 110, 0> translate <-54, 15, -20> }
