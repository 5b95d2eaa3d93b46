// Loads a light model (raymodel build LED.TM25RAY -o LED.vdb) and samples it as a renderer would:
// photons from its emission, and light arriving at a point from its body.
//
// Usage: consumer MODEL.vdb [PHOTONS]
// Prints the model's flux, the mean flux of the photons drawn (the flux again, within its
// Monte Carlo error) and the irradiance estimated by light sampling 100 mm above the source.
#include <rayset/model.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: consumer MODEL.vdb [PHOTONS]\n");
        return 2;
    }
    const long photons = argc > 2 ? std::atol(argv[2]) : 100000;
    try {
        auto model = std::make_shared<const rayset::LightModel>(rayset::read_model(argv[1]));
        const rayset::ComplexSource source(model);
        rayset::Pcg32 rng(1);

        // Photon emission: each photon carries its flux divided by the densities it was drawn
        // with, so their mean is the source's flux.
        double sum = 0, square = 0;
        for (long i = 0; i < photons; ++i) {
            double u[7];
            for (double& v : u) v = rng.uniform();
            const double flux = source.sample_Le(u).flux;
            sum += flux, square += flux * flux;
        }
        const double mean = sum / photons;
        const double error = std::sqrt(std::max(0.0, square / photons - mean * mean) / photons);

        // Light sampling: irradiance at a point 100 mm above the source, normal toward it.
        const rayset::Vec3 point{0, 0, 100};
        double irradiance = 0;
        for (long i = 0; i < photons; ++i) {
            const auto s = source.sample_Li(point, rng.uniform(), rng.uniform(),
                                            {rng.uniform(), rng.uniform(), rng.uniform()});
            if (s && s->pdf > 0) irradiance += s->Li * std::max(0.0, -s->wi.z) / s->pdf;
        }
        std::printf("flux %.9g\nphoton mean %.9g +- %.3g\nirradiance at 100 mm %.6g\n",
                    source.phi(), mean, error, irradiance / photons);
    } catch (const rayset::Error& e) {
        std::fprintf(stderr, "consumer: %s\n", e.what());
        return 1;
    }
    return 0;
}
