// Macros of the standard include files: math.inc and transforms.inc.
#version 3.7;
#macro F(Label, V) #debug concat(Label, " ", str(V, 0, 9), "\n") #end
#macro V3(Label, V) #debug concat(Label, " ", vstr(3, V, ",", 0, 9), "\n") #end
#include "math.inc"
#include "transforms.inc"
F("even", even(4) + odd(4) * 2 + even(7) * 4 + odd(7) * 8)
F("interp-lin", Interpolate(0.3, 0, 1, 10, 20, 1))
F("interp-pow", Interpolate(0.3, 0, 1, 10, 20, 2))
F("adj", adj_range(0.5, -1, 3) + adj_range2(5, 0, 10, -1, 1))
F("sgn", sgn(-2) + sgn(0) * 10 + sgn(3) * 100)
F("clip", clip(5, 0, 3) + clip(-2, 0, 3) * 10)
F("clamp", clamp(7.5, 0, 3))
F("max3", max3(3, 9, -2) + min3(3, 9, -2))
F("deg", f_sqr(3) + sind(30) + cosd(60) + tand(45) + asind(0.5) + acosd(0.5) + atand(1) + atan2d(1, -1))
F("vmin", VMin(<3, -1, 2>) + VMax(<3, -1, 2>) * 10)
V3("vsqr", VSqr(<1, -2, 3>))
V3("vpow", VPow(<1, 2, 3>, 2.5))
F("veq", VEq(<1, 2, 3>, <1, 2, 3>) + VZero(<0, 0, 1e-9>) * 2)
F("vangle", VAngle(<1, 0, 0>, <1, 1, 0>) + VAngleD(<1, 0, 0>, <0, 1, 1>))
F("vcos", VCos_Angle(<1, 2, 3>, <-2, 1, 0.5>))
V3("vperp", VPerp_To_Vector(<1, 2, 3>))
V3("vperp2", VPerp_To_Plane(<1, 0, 0>, <0, 1, 1>))
V3("vperpadj", VPerp_Adjust(<1, 1, 0>, <0, 1, 0>))
V3("vprojp", VProject_Plane(<1, 2, 3>, <0, 1, 0>))
V3("vproja", VProject_Axis(<1, 2, 3>, <1, 1, 0>))
F("vdist", VDist(<1, 2, 3>, <4, 6, 3>))
V3("vwithlen", VWith_Len(<3, 4, 0>, 10))
F("vrotation", VRotationD(<1, 0, 0>, <0, 1, 0>, <0, 0, 1>))
#declare Pt = <1, 2, 3>;
V3("shear", vtransform(Pt, Shear_Trans(<1, 0.5, 0>, <0, 1, 0>, <0.2, 0, 1>)))
V3("matrix", vtransform(Pt, Matrix_Trans(<1, 0, 0>, <0, 2, 0>, <0, 0, 3>, <4, 5, 6>)))
V3("axialscale", vtransform(Pt, Axial_Scale_Trans(<1, 1, 0>, 2)))
V3("axisrot", vtransform(Pt, Axis_Rotate_Trans(<0, 1, 1>, 40)))
V3("rotaround", vtransform(Pt, Rotate_Around_Trans(<0, 90, 0>, <1, 0, 1>)))
V3("reorient", vtransform(Pt, Reorient_Trans(<1, 0, 0>, <0, 1, 1>)))
V3("pointat", vtransform(Pt, Point_At_Trans(<1, 1, 1>)))
V3("invtrans", vinv_transform(Pt, transform { rotate <10, 20, 30> scale <1, 2, 4> translate 3 }))
#declare TT = transform { translate <1, 2, 3> rotate 45 * y scale 2 }
V3("declared", vtransform(<1, 0, 0>, TT))
V3("inverse", vtransform(<1, 0, 0>, transform { TT inverse }))
