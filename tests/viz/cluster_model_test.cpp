// The acceptance tests of the model views on the synthetic 39-chip cluster (1e6 rays, seed 7):
// exported spheres form 39 separate blobs, the rendered PNG shows them with a scalar bar, the
// exported diagrams have the chips' Lambertian lobe, and re-read files match the model.
#include <gtest/gtest.h>

#include "converters/analytic/analytic_sources.h"
#include "viz/diagram_surface.h"
#include "viz/export.h"
#include "viz/scene.h"
#include "viz/viz_support.h"
#include "viz/vtk_arrays.h"

#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLMultiBlockDataReader.h>
#include <vtkXMLPolyDataReader.h>

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <numeric>
#include <tuple>

namespace {

using namespace rayset;

vtkSmartPointer<vtkPolyData> read_polydata(const std::string& path) {
    auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    reader->SetFileName(path.c_str());
    reader->Update();
    return reader->GetOutput();
}

vtkSmartPointer<vtkImageData> read_image(const std::string& path) {
    auto reader = vtkSmartPointer<vtkXMLImageDataReader>::New();
    reader->SetFileName(path.c_str());
    reader->Update();
    return reader->GetOutput();
}

// The model exported once for all tests here.
const std::string& export_dir() {
    static test::ScratchDir scratch;
    static std::string dir;
    if (dir.empty()) {
        viz::Input input(test::cluster_model_file());
        viz::export_input(input, {}, scratch.file("export"));
        dir = scratch.file("export");
    }
    return dir;
}

// Union-find over spheres that overlap or touch, neighbours found through a grid of cells as
// large as the largest diameter.
int connected_components(vtkPolyData* spheres) {
    const vtkIdType n = spheres->GetNumberOfPoints();
    vtkDataArray* radius = spheres->GetPointData()->GetArray("radius");
    double largest = 0;
    for (vtkIdType i = 0; i < n; ++i) largest = std::max(largest, radius->GetComponent(i, 0));
    const double cell = 2 * largest;
    std::map<std::tuple<long, long, long>, std::vector<vtkIdType>> grid;
    auto key = [&](const double* p, int dx, int dy, int dz) {
        return std::make_tuple(long(std::floor(p[0] / cell)) + dx,
                               long(std::floor(p[1] / cell)) + dy,
                               long(std::floor(p[2] / cell)) + dz);
    };
    for (vtkIdType i = 0; i < n; ++i) grid[key(spheres->GetPoint(i), 0, 0, 0)].push_back(i);
    std::vector<vtkIdType> parent(n);
    std::iota(parent.begin(), parent.end(), 0);
    std::function<vtkIdType(vtkIdType)> root = [&](vtkIdType i) {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    };
    for (vtkIdType i = 0; i < n; ++i) {
        double p[3];
        spheres->GetPoint(i, p);
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dz = -1; dz <= 1; ++dz) {
                    auto found = grid.find(key(p, dx, dy, dz));
                    if (found == grid.end()) continue;
                    for (vtkIdType j : found->second) {
                        if (j <= i) continue;
                        double q[3];
                        spheres->GetPoint(j, q);
                        const double d = std::sqrt((p[0] - q[0]) * (p[0] - q[0]) +
                                                   (p[1] - q[1]) * (p[1] - q[1]) +
                                                   (p[2] - q[2]) * (p[2] - q[2]));
                        if (d <= radius->GetComponent(i, 0) + radius->GetComponent(j, 0))
                            parent[root(i)] = root(j);
                    }
                }
    }
    int components = 0;
    for (vtkIdType i = 0; i < n; ++i) components += root(i) == i;
    return components;
}

}  // namespace

TEST(ClusterModelViews, ExportedSpheresFormOneBlobPerChip) {
    auto spheres = read_polydata(export_dir() + "/spheres.vtp");
    ASSERT_GT(spheres->GetNumberOfPoints(), 39);
    const int components = connected_components(spheres);
    RecordProperty("spheres", int(spheres->GetNumberOfPoints()));
    RecordProperty("components", components);
    EXPECT_EQ(components, 39);
}

TEST(ClusterModelViews, SpheresPngShowsTheBodyAndItsScalarBar) {
    test::ScratchDir dir;
    viz::Input input(test::cluster_model_file());
    viz::SceneOptions options;
    options.width = 800, options.height = 600, options.offscreen = true;
    viz::Scene scene = viz::build_scene(input, nullptr, viz::View::spheres, {}, options);
    viz::write_png(scene, dir.file("spheres.png"));
    // The scalar bar's colour strip lies in x 0.86..0.98, y 0.1..0.9 of the window
    // (view_style.cpp).
    const double bar[4] = {0.86, 0.98, 0.1, 0.9};
    const test::PngStatistics s = test::png_statistics(dir.file("spheres.png"), bar);
    EXPECT_EQ(s.width, 800);
    EXPECT_EQ(s.height, 600);
    // Not blank: the 39 chips (1 mm squares spread over 13 mm) cover a few percent of the window.
    EXPECT_GT(s.foreground, 0.03 * s.width * s.height);
    // The bar is a colour gradient: many distinct colours there, not just text.
    EXPECT_GT(s.region_foreground, 0.3 * 0.12 * 0.8 * 0.5 * s.width * s.height);
    RecordProperty("foreground_fraction",
                   std::to_string(double(s.foreground) / (s.width * s.height)));
    RecordProperty("bar_colours", s.region_colours);
    EXPECT_GT(s.region_colours, 50);
}

TEST(ClusterModelViews, CentreCellDiagramIsTheLambertianLobe) {
    const auto& model = *test::built_source("cluster").model;
    // The cluster is flat (one layer of cells in z); the centre chip is in the middle cell.
    const lightmodel::Coord centre{model.intensity_frame.dims()[0] / 2,
                                   model.intensity_frame.dims()[1] / 2, 0};
    ASSERT_EQ(centre, (lightmodel::Coord{2, 2, 0}));
    auto diagram = read_polydata(
        fmt::format("{}/diagram_{}_{}_{}.vtp", export_dir(), centre[0], centre[1], centre[2]));
    ASSERT_EQ(diagram->GetNumberOfPoints(),
              2 + 89 * 72);  // 90 rings, 72 sectors (diagram_surface.h)
    const double cell_flux = viz::field_values(diagram, "cell_flux").at(0);
    const double ray_flux = 1e-6;  // 1 W over 1e6 equal rays
    const double rays = cell_flux / ray_flux;
    ASSERT_GT(rays, 20000);

    // Every chip is Lambertian toward +z: the cell's intensity is Phi_k cos(theta) / pi.
    // +z pole: the diagram extrapolates it from the ring means of the two top bands of 40
    // (u in [0.95, 1] and [0.9, 0.95], 9.75% and 9.25% of a Lambertian cell's rays):
    // pole = 1.5 m1 - 0.5 m2, relative sigma = sqrt(2.25 / (0.0975 n) + 0.25 / (0.0925 n)).
    // 4 sigma: a false failure has probability < 1e-4 (normal approximation, n > 2e4 rays).
    double pole[3];
    diagram->GetPoint(0, pole);
    const double radius_z = pole[2];
    EXPECT_NEAR(pole[0], 0, 1e-12);
    EXPECT_NEAR(pole[1], 0, 1e-12);
    const double expected = cell_flux / kPi;
    const double sigma = std::sqrt(2.25 / (0.0975 * rays) + 0.25 / (0.0925 * rays));
    RecordProperty("pole_ratio", std::to_string(radius_z / expected));
    RecordProperty("pole_bound", std::to_string(4 * sigma));
    RecordProperty("cell_rays", std::to_string(rays));
    EXPECT_NEAR(radius_z / expected, 1, 4 * sigma)
        << "radius along +z " << radius_z << ", Phi_k/pi " << expected << ", rays " << rays;

    // The lobe's shape: ring means at theta = 30 and 60 degrees (rings 15 and 30 of 90) against
    // cos(theta). Each interpolates between neighbouring bands of 12 cells holding about
    // 2 u du = 2 cos(theta) / 40 of the rays; sigma of a band mean is 1 / sqrt(that count), 4
    // sigma.
    vtkDataArray* intensity = diagram->GetPointData()->GetArray("intensity");
    for (int ring : {15, 30}) {
        const double theta = kPi * ring / 90;
        double mean = 0;
        for (int i = 0; i < 72; ++i)
            mean += intensity->GetComponent(1 + (ring - 1) * 72 + i, 0) / 72;
        const double band_rays = rays * 2 * std::cos(theta) / 40;
        RecordProperty("ring_" + std::to_string(ring),
                       std::to_string(mean / (expected * std::cos(theta))));
        EXPECT_NEAR(mean / (expected * std::cos(theta)), 1, 4 / std::sqrt(band_rays))
            << "theta " << theta;
    }
}

TEST(ClusterModelViews, DiagramsAddUpToTheClusterIntensity) {
    // Summed over all intensity cells, the radius along +z is the model's intensity toward +z,
    // which for 39 Lambertian chips of 1/39 W is the analytic 1 / pi W/sr. Each cell's pole has
    // the relative sigma of the test above; over all 1e6 rays that is 0.5%; 4 sigma.
    const auto& cluster = test::built_source("cluster");
    double sum = 0;
    int diagrams = 0;
    for (const auto& entry : std::filesystem::directory_iterator(export_dir())) {
        if (entry.path().filename().string().rfind("diagram_", 0) != 0) continue;
        auto d = read_polydata(entry.path().string());
        sum += d->GetPoint(0)[2];
        ++diagrams;
    }
    EXPECT_EQ(diagrams, int(cluster.model->diagrams.size()));
    const double truth = cluster.truth->intensity({0, 0, 1});
    EXPECT_NEAR(truth, 1 / kPi, 1e-12);
    const double sigma = std::sqrt(2.25 / (0.0975 * 1e6) + 0.25 / (0.0925 * 1e6));
    RecordProperty("sum_ratio", std::to_string(sum / truth));
    RecordProperty("sum_bound", std::to_string(4 * sigma));
    EXPECT_NEAR(sum / truth, 1, 4 * sigma) << "sum " << sum;
}

TEST(ClusterModelViews, ExportedFilesReadBackAsTheModel) {
    const auto& model = *test::built_source("cluster").model;
    auto density = read_image(export_dir() + "/density.vti");
    const auto& dims = model.density_frame.dims();
    int read_dims[3];
    density->GetDimensions(read_dims);
    EXPECT_EQ(read_dims[0], dims[0]);
    EXPECT_EQ(read_dims[1], dims[1]);
    EXPECT_EQ(read_dims[2], dims[2]);
    EXPECT_DOUBLE_EQ(density->GetSpacing()[0], model.density_frame.cell_size());
    vtkDataArray* counts = density->GetPointData()->GetArray("density");
    ASSERT_NE(counts, nullptr);
    long occupied = 0;
    double total = 0;
    for (vtkIdType i = 0; i < counts->GetNumberOfTuples(); ++i) {
        occupied += counts->GetComponent(i, 0) > 0;
        total += counts->GetComponent(i, 0);
    }
    EXPECT_EQ(occupied, long(model.voxels.size()));
    EXPECT_EQ(total, double(model.source.rays));  // every ray counted once, counts exact in float
    double range[2];
    counts->GetRange(range);
    EXPECT_EQ(range[1], *std::max_element(model.voxel_density.begin(), model.voxel_density.end()));
    // The voxel at the model's first voxel holds its count (same index order as the lattice).
    const auto& v0 = model.voxels.front();
    EXPECT_EQ(counts->GetComponent(density->ComputePointId(const_cast<int*>(v0.data())), 0),
              model.voxel_density.front());

    auto flux = read_image(export_dir() + "/flux.vti");
    vtkDataArray* cell_flux = flux->GetPointData()->GetArray("flux");
    ASSERT_NE(cell_flux, nullptr);
    long lit = 0;
    double flux_total = 0;
    for (vtkIdType i = 0; i < cell_flux->GetNumberOfTuples(); ++i) {
        lit += cell_flux->GetComponent(i, 0) > 0;
        flux_total += cell_flux->GetComponent(i, 0);
    }
    EXPECT_EQ(lit, long(model.flux_cells.size()));
    EXPECT_NEAR(flux_total, model.total_flux(), 1e-12 * model.total_flux());
    EXPECT_NEAR(flux_total, 1.0,
                1e-6);  // the synthetic cluster's 1 W, to float rounding of the rays

    auto spheres = read_polydata(export_dir() + "/spheres.vtp");
    EXPECT_EQ(spheres->GetNumberOfPoints(), vtkIdType(model.spheres.size()));
    double radii[2];
    spheres->GetPointData()->GetArray("radius")->GetRange(radii);
    const auto [smallest, largest] =
        std::minmax_element(model.spheres.begin(), model.spheres.end(),
                            [](const auto& a, const auto& b) { return a.r < b.r; });
    EXPECT_EQ(radii[0], smallest->r);
    EXPECT_EQ(radii[1], largest->r);

    // The collection names every file; VTK's multiblock reader loads them all.
    auto collection = vtkSmartPointer<vtkXMLMultiBlockDataReader>::New();
    collection->SetFileName((export_dir() + "/cluster.vtm").c_str());
    collection->Update();
    auto* blocks = vtkMultiBlockDataSet::SafeDownCast(collection->GetOutput());
    ASSERT_NE(blocks, nullptr);
    EXPECT_EQ(blocks->GetNumberOfBlocks(), 3 + model.diagrams.size());
    auto* first = vtkImageData::SafeDownCast(blocks->GetBlock(0));
    ASSERT_NE(first, nullptr);
    EXPECT_EQ(first->GetNumberOfPoints(), model.density_frame.cell_count());
    auto* third = vtkPolyData::SafeDownCast(blocks->GetBlock(2));
    ASSERT_NE(third, nullptr);
    EXPECT_EQ(third->GetNumberOfPoints(), vtkIdType(model.spheres.size()));
}
