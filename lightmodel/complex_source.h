// The paper's complex light source behind the emitter interface: the sphere body for what
// rays hit, the emission volume for what they see and for light sampling, the goniometric
// diagrams for photon directions. How the three stay consistent: docs/light-model.md.
#pragma once

#include "lightmodel/emitter.h"
#include "lightmodel/model.h"
#include "lightmodel/sphere_body.h"
#include "lightmodel/voxel_balls.h"

#include <memory>

namespace rayset::lightmodel {

class ComplexSource : public Emitter {
public:
    explicit ComplexSource(std::shared_ptr<const LightModel> model);

    const LightModel& model() const { return *model_; }
    const SphereBody& body() const { return body_; }
    const EmissionVolume& volume() const { return volume_; }

    double phi(const SpectralSelect& select = {}) const override { return volume_.total(select); }
    Box bounds() const override { return bounds_; }
    Rgb phi_colour() const override { return volume_.total_colour(); }
    bool intersect(Vec3 origin, Vec3 dir, double tmax, EmitterHit& hit) const override;
    double L(Vec3 origin, Vec3 dir, const EmitterHit& hit,
             const SpectralSelect& select = {}) const override;
    Rgb L_colour(Vec3 origin, Vec3 dir, const EmitterHit& hit) const override;
    void L_spectral(Vec3 origin, Vec3 dir, const EmitterHit& hit,
                    SpectralQuery& query) const override;
    BinnedSpectrum phi_spectrum() const override { return volume_.total_spectrum(); }
    std::optional<LiSample> sample_Li(Vec3 ref, double u_cell, double u_voxel, Vec3 u_point,
                                      const SpectralSelect& select = {},
                                      SpectralQuery* spectral = nullptr,
                                      BodyEntry entry = BodyEntry::wanted) const override;
    double pdf_Li(Vec3 ref, Vec3 wi) const override;
    bool enters_body_near(int64_t voxel, Vec3 origin, Vec3 dir, double t_max) const override {
        return voxel >= 0 && voxel_balls_.ray_enters(uint32_t(voxel), origin, dir, t_max);
    }
    LeSample sample_Le(const double u[7], const SpectralSelect& select = {}) const override;
    void pdf_Le(Vec3 origin, Vec3 direction, double& pdf_position,
                double& pdf_direction) const override;
    double pdf_Le_line(Vec3 origin, Vec3 dir) const override {
        return volume_.line_density(origin, dir);
    }
    // One traversal of the emitting volume.
    EmitterLine line(Vec3 origin, Vec3 dir, bool with_pdf_Le,
                     SpectralQuery* spectral) const override;

    // Far-field radiant intensity of the model toward `w` (flux/sr): sum over flux cells of
    // Phi_c D_k(w). What sample_Le emits and what the camera sees from far away.
    double intensity(Vec3 w, const SpectralSelect& select = {}) const;

    // Light sampling from farther than this many radii of the sphere around the emitting volume
    // estimates with the sampled point alone (EmissionVolume::point_estimate) and is weighed
    // for MIS by the uniform density over that sphere's cone (pdf_Li says the same); nearer,
    // with the radiance and the exact density of the point's whole line. Beyond 4 radii the
    // point's distance varies by less than 5:3 over the volume, so the point estimate's
    // variance stays near the line's, without the line's traversal and its diagram lookups.
    static constexpr double kFarRadii = 4;

private:
    struct BoundingSphere {
        Vec3 centre;
        double radius = 0;
    };

    // Whether the ray from `ref` along `wi` meets the body, `voxel` the sampled point's.
    bool meets_body(Vec3 ref, Vec3 wi, uint32_t voxel) const;
    bool far_from(Vec3 ref) const;
    double cone_density(Vec3 ref, Vec3 wi) const;

    std::shared_ptr<const LightModel> model_;
    EmissionVolume volume_;
    SphereBody body_;
    VoxelBalls voxel_balls_;
    Box bounds_;
    BoundingSphere reach_;              // around the occupied voxels
    std::vector<double> diagram_flux_;  // flux of the cells that use each diagram
};

}  // namespace rayset::lightmodel
