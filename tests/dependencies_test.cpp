// The third-party stack works as the project uses it: each library does one small real job
// whose answer is known. A failure here means the machine's packages, not our code.
#include <gtest/gtest.h>

#include "support/test_support.h"

#include <ImfArray.h>
#include <ImfRgbaFile.h>
#include <ceres/ceres.h>
#include <embree3/rtcore.h>
#include <openvdb/openvdb.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSphereSource.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <cmath>
#include <limits>

TEST(Dependencies, EmbreeIntersectsASpherePoint) {
    RTCDevice device = rtcNewDevice(nullptr);
    ASSERT_NE(device, nullptr);
    RTCScene scene = rtcNewScene(device);
    RTCGeometry sphere = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(sphere, RTC_BUFFER_TYPE_VERTEX, 0,
                                                          RTC_FORMAT_FLOAT4, 4 * sizeof(float), 1));
    v[0] = 0, v[1] = 0, v[2] = 10, v[3] = 2;  // centre (0,0,10), radius 2
    rtcCommitGeometry(sphere);
    rtcAttachGeometry(scene, sphere);
    rtcReleaseGeometry(sphere);
    rtcCommitScene(scene);

    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh{};
    rh.ray.org_x = 0, rh.ray.org_y = 0, rh.ray.org_z = 0;
    rh.ray.dir_x = 0, rh.ray.dir_y = 0, rh.ray.dir_z = 1;
    rh.ray.tnear = 0, rh.ray.tfar = std::numeric_limits<float>::infinity();
    rh.ray.mask = ~0u;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &context, &rh);
    EXPECT_NE(rh.hit.geomID, RTC_INVALID_GEOMETRY_ID);
    EXPECT_NEAR(rh.ray.tfar, 8.0f, 1e-4f);  // front of the sphere
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
}

TEST(Dependencies, OpenVdbGridRoundTripsThroughAFile) {
    openvdb::initialize();
    auto grid = openvdb::FloatGrid::create(0.0f);
    grid->setName("density");
    auto accessor = grid->getAccessor();
    for (int i = 0; i < 10; ++i) accessor.setValue(openvdb::Coord(i, 2 * i, -i), float(i) + 0.5f);
    rayset::test::ScratchDir dir;
    openvdb::io::File out(dir.file("grid.vdb"));
    out.write({grid});
    out.close();

    openvdb::io::File in(dir.file("grid.vdb"));
    in.open();
    auto read = openvdb::gridPtrCast<openvdb::FloatGrid>(in.readGrid("density"));
    in.close();
    ASSERT_TRUE(read);
    EXPECT_EQ(read->activeVoxelCount(), 10u);
    EXPECT_EQ(read->getConstAccessor().getValue(openvdb::Coord(7, 14, -7)), 7.5f);
}

namespace {
struct DistanceToSphere {
    DistanceToSphere(double x, double y, double z) : x(x), y(y), z(z) {}
    template <class T>
    bool operator()(const T* centre, const T* radius, T* residual) const {
        T dx = centre[0] - T(x), dy = centre[1] - T(y), dz = centre[2] - T(z);
        residual[0] = ceres::sqrt(dx * dx + dy * dy + dz * dz) - radius[0];
        return true;
    }
    double x, y, z;
};
}  // namespace

TEST(Dependencies, CeresFitsASphereToPointsOnIt) {
    // Points on a sphere of centre (1, -2, 3) and radius 4 (Fibonacci lattice, exact).
    double centre[3] = {0, 0, 0}, radius = 1;
    ceres::Problem problem;
    const int n = 200;
    for (int i = 0; i < n; ++i) {
        double z = 1 - (2.0 * i + 1) / n, r = std::sqrt(1 - z * z), phi = i * 2.399963229728653;
        problem.AddResidualBlock(
            new ceres::AutoDiffCostFunction<DistanceToSphere, 1, 3, 1>(new DistanceToSphere(
                1 + 4 * r * std::cos(phi), -2 + 4 * r * std::sin(phi), 3 + 4 * z)),
            nullptr, centre, &radius);
    }
    ceres::Solver::Options options;
    ceres::Solver::Summary summary;
    ceres::Solve(options, &problem, &summary);
    EXPECT_NEAR(centre[0], 1, 1e-6);
    EXPECT_NEAR(centre[1], -2, 1e-6);
    EXPECT_NEAR(centre[2], 3, 1e-6);
    EXPECT_NEAR(radius, 4, 1e-6);
}

TEST(Dependencies, OpenExrImageRoundTrips) {
    rayset::test::ScratchDir dir;
    const int w = 4, h = 3;
    Imf::Array2D<Imf::Rgba> pixels(h, w);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) pixels[y][x] = Imf::Rgba(float(x), float(y), 0.25f, 1.0f);
    {
        Imf::RgbaOutputFile out(dir.file("image.exr").c_str(), w, h, Imf::WRITE_RGBA);
        out.setFrameBuffer(&pixels[0][0], 1, w);
        out.writePixels(h);
    }
    Imf::RgbaInputFile in(dir.file("image.exr").c_str());
    Imf::Array2D<Imf::Rgba> back(h, w);
    in.setFrameBuffer(&back[0][0], 1, w);
    in.readPixels(0, h - 1);
    EXPECT_EQ(float(back[2][3].r), 3.0f);
    EXPECT_EQ(float(back[2][3].g), 2.0f);
    EXPECT_EQ(float(back[1][1].b), 0.25f);
}

TEST(Dependencies, VtkWritesAndReadsPolyData) {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetThetaResolution(16);
    sphere->SetPhiResolution(8);
    sphere->Update();
    // A UV sphere of 16 x 8 has 16 * (8 - 2) + 2 points.
    EXPECT_EQ(sphere->GetOutput()->GetNumberOfPoints(), 16 * 6 + 2);
    rayset::test::ScratchDir dir;
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetFileName(dir.file("sphere.vtp").c_str());
    writer->SetInputConnection(sphere->GetOutputPort());
    ASSERT_EQ(writer->Write(), 1);
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(dir.file("sphere.vtp").c_str());
    reader->Update();
    EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 16 * 6 + 2);
}

TEST(Dependencies, TbbReducesInParallel) {
    const long n = 1000000;
    long sum = tbb::parallel_reduce(
        tbb::blocked_range<long>(1, n + 1), 0L,
        [](const tbb::blocked_range<long>& r, long s) {
            for (long i = r.begin(); i != r.end(); ++i) s += i;
            return s;
        },
        std::plus<long>());
    EXPECT_EQ(sum, n * (n + 1) / 2);
}
