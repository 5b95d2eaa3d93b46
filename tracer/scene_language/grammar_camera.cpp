// camera { }: every projection, its vectors resolved as POV-Ray 3.5+ resolves them (the type
// first; the other items in any order, then applied as angle, look_at, orthographic sizing and
// transforms), focal blur, normal perturbation, mesh_camera and declared cameras.
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "tracer/scene_language/grammar.h"

namespace rayset::tracer {
namespace {

struct ProjectionKeyword {
    Keyword keyword;
    CameraProjection projection;
};
constexpr ProjectionKeyword kProjections[] = {
    {Keyword::perspective, CameraProjection::perspective},
    {Keyword::orthographic, CameraProjection::orthographic},
    {Keyword::mesh_camera, CameraProjection::mesh},
    {Keyword::fisheye, CameraProjection::fisheye},
    {Keyword::ultra_wide_angle, CameraProjection::ultra_wide_angle},
    {Keyword::omnimax, CameraProjection::omnimax},
    {Keyword::panoramic, CameraProjection::panoramic},
    {Keyword::cylinder, CameraProjection::cylinder},
    {Keyword::spherical, CameraProjection::spherical},
};

const ProjectionKeyword* projection_of(const Token& token) {
    for (const ProjectionKeyword& entry : kProjections)
        if (token.is(entry.keyword)) return &entry;
    return nullptr;
}

// What the block says that is applied after all of it is read.
struct CameraItems {
    std::optional<Vec3> look_at;
    Token look_at_token;
    bool angle_given = false;     // the angle keyword, with or without a value
    std::optional<double> angle;  // its value
    std::optional<double> vertical_angle;
    Token angle_token;
    bool up_or_right_given = false;
    Matrix4 transform;
};

void transform_camera(Camera& camera, const Matrix4& transform) {
    camera.location = transform.point(camera.location);
    camera.direction = transform.vector(camera.direction);
    camera.up = transform.vector(camera.up);
    camera.right = transform.vector(camera.right);
    camera.sky = transform.vector(camera.sky);
    camera.focal_blur.focal_point = transform.point(camera.focal_blur.focal_point);
    camera.transform = transform * camera.transform;
}

// mesh_camera { rays_per_pixel distribution [max_distance] mesh { } ... [smooth] }, with POV-Ray's
// checks of how the counts fit the distribution.
void parse_mesh_camera(Parser& p, const Token& keyword, MeshCamera& mesh) {
    const Token open = p.expect_open(keyword);
    const Token rays_token = p.peek();
    mesh.rays_per_pixel = p.parse_int("as the mesh_camera's rays per pixel", 1);
    const Token distribution_token = p.peek();
    mesh.distribution = p.parse_int("as the mesh_camera's distribution", 0);
    if (mesh.distribution > 3)
        p.fail(distribution_token, fmt::format("unknown mesh_camera distribution {} (expected 0, "
                                               "1, 2 or 3)",
                                               mesh.distribution));
    if (p.starts_expression(p.peek()))
        mesh.max_distance = p.parse_float("as the mesh_camera's max distance");
    Token smooth_token;
    for (;;) {
        const Token token = p.peek();
        if (token.is(Symbol::rbrace)) break;
        if (token.is(Keyword::mesh) || token.is(Keyword::mesh2)) {
            mesh.meshes.push_back(parse_object(p));
        } else if (token.is(Keyword::smooth)) {
            smooth_token = p.next();
            mesh.smooth = true;
        } else {
            p.fail_identifier(token, fmt::format("mesh, mesh2, smooth or '}}' to close "
                                                 "'mesh_camera' opened at {}",
                                                 p.location_of(open).str()));
        }
    }
    if (mesh.meshes.empty()) p.fail_expected("a mesh or mesh2 in the mesh_camera", p.peek());
    p.expect_close(keyword, open);
    if (mesh.distribution == 0 && mesh.rays_per_pixel > static_cast<int>(mesh.meshes.size()))
        p.fail(rays_token, fmt::format("mesh_camera distribution 0 takes at most one ray per "
                                       "pixel per mesh: {} rays per pixel, {} meshes",
                                       mesh.rays_per_pixel, mesh.meshes.size()));
    if (mesh.distribution >= 2 && mesh.rays_per_pixel != 1)
        p.fail(rays_token, fmt::format("mesh_camera distribution {} takes 1 ray per pixel, "
                                       "found {}",
                                       mesh.distribution, mesh.rays_per_pixel));
    if (mesh.smooth && mesh.distribution != 3)
        p.fail(smooth_token, fmt::format("'smooth' needs mesh_camera distribution 3, found {}",
                                         mesh.distribution));
}

// The projection keyword(s) that may open the block; a later one replaces an earlier one.
void parse_projection(Parser& p, Camera& camera) {
    while (const ProjectionKeyword* entry = projection_of(p.peek())) {
        const Token token = p.next();
        camera.projection = entry->projection;
        camera.projection_location = p.location_of(token);
        if (entry->projection == CameraProjection::cylinder) {
            const Token at = p.peek();
            const double type = std::trunc(p.parse_float("as the cylinder camera's type"));
            if (!(type >= 1 && type <= 4))
                p.fail(at, fmt::format("cylinder camera type {} (expected 1, 2, 3 or 4)", type));
            camera.cylinder_type = static_cast<int>(type);
        } else if (entry->projection == CameraProjection::mesh) {
            camera.mesh = MeshCamera{};
            parse_mesh_camera(p, token, camera.mesh);
        }
    }
}

// angle H: an orthographic camera's value is optional, a spherical camera takes a vertical one too.
void parse_angle(Parser& p, const Token& keyword, const Camera& camera, CameraItems& items) {
    if (camera.projection == CameraProjection::mesh)
        p.fail(keyword,
               "'angle' does not apply to a mesh_camera (its rays come from the mesh faces)");
    items.angle_given = true;
    items.angle_token = p.peek();
    const bool orthographic = camera.projection == CameraProjection::orthographic;
    if (orthographic && !p.starts_expression(p.peek())) return;
    const bool spherical = camera.projection == CameraProjection::spherical;
    items.angle = p.parse_float("after 'angle'");
    if (*items.angle < 0)
        p.fail(items.angle_token, fmt::format("the camera's {}angle must not be negative, found {}",
                                              spherical ? "horizontal " : "", *items.angle));
    if (!spherical || !(p.accept(Symbol::comma) || p.starts_expression(p.peek()))) return;
    const Token vertical_token = p.peek();
    items.vertical_angle = p.parse_float("as the vertical angle");
    if (*items.vertical_angle < 0)
        p.fail(vertical_token,
               fmt::format("the camera's vertical angle must not be negative, found {}",
                           *items.vertical_angle));
}

// blur_samples [MIN,] MAX: POV-Ray's minimum is 4 below 7 samples, else 7 (here never above
// the maximum).
void parse_blur_samples(Parser& p, FocalBlur& blur) {
    const Token first_token = p.peek();
    const int first = p.parse_int("after 'blur_samples'", 1);
    if (!(p.accept(Symbol::comma) || p.starts_expression(p.peek()))) {
        blur.max_samples = first;
        blur.min_samples = std::min(first, first < 7 ? 4 : 7);
        return;
    }
    blur.min_samples = first;
    blur.max_samples = p.parse_int("as the maximum of 'blur_samples'", 1);
    if (blur.min_samples > blur.max_samples)
        p.fail(first_token, fmt::format("blur_samples: the minimum {} is larger than the "
                                        "maximum {}",
                                        blur.min_samples, blur.max_samples));
}

// bokeh { pigment { } }
void parse_bokeh(Parser& p, const Token& keyword, FocalBlur& blur) {
    const Token open = p.expect_open(keyword);
    while (!p.peek_is(Symbol::rbrace)) {
        const Token token = p.next();
        if (!token.is(Keyword::pigment))
            p.fail_identifier(token, fmt::format("pigment or '}}' to close 'bokeh' opened at {}",
                                                 p.location_of(open).str()));
        blur.bokeh = parse_pigment(p, token);
    }
    p.expect_close(keyword, open);
}

// A focal blur item (aperture, blur_samples, focal_point, confidence, variance, bokeh); false
// (nothing read) for anything else.
bool parse_focal_blur_item(Parser& p, Camera& camera) {
    const Token token = p.peek();
    FocalBlur& blur = camera.focal_blur;
    if (token.is(Keyword::aperture)) {
        p.next();
        blur.aperture = p.parse_float("after 'aperture'");
        camera.focal_blur_location = p.location_of(token);
    } else if (token.is(Keyword::blur_samples)) {
        p.next();
        parse_blur_samples(p, blur);
    } else if (token.is(Keyword::focal_point)) {
        p.next();
        blur.focal_point = p.parse_vector();
    } else if (token.is(Keyword::confidence)) {
        p.next();
        blur.confidence = p.parse_float("after 'confidence'");
    } else if (token.is(Keyword::variance)) {
        p.next();
        blur.variance = p.parse_float("after 'variance'");
        if (blur.variance == 1) {  // POV-Ray's rule: 1 means its default, with a warning
            p.warn(token, "focal blur variance 1 replaced by the default 1/128");
            blur.variance = FocalBlur{}.variance;
        }
    } else if (token.is(Keyword::bokeh)) {
        p.next();
        parse_bokeh(p, token, blur);
    } else {
        return false;
    }
    return true;
}

// One item after the projection; false when the token starts none.
bool parse_camera_item(Parser& p, Camera& camera, CameraItems& items) {
    const Token token = p.peek();
    if (p.parse_transform_item(items.transform)) return true;
    if (parse_focal_blur_item(p, camera)) return true;
    const struct {
        Keyword keyword;
        Vec3* vector;
    } vectors[] = {{Keyword::location, &camera.location},
                   {Keyword::direction, &camera.direction},
                   {Keyword::up, &camera.up},
                   {Keyword::right, &camera.right},
                   {Keyword::sky, &camera.sky}};
    for (const auto& entry : vectors)
        if (token.is(entry.keyword)) {
            p.next();
            *entry.vector = p.parse_vector();
            if (token.is(Keyword::up) || token.is(Keyword::right)) items.up_or_right_given = true;
            return true;
        }
    if (token.is(Keyword::look_at)) {
        items.look_at_token = p.next();
        items.look_at = p.parse_vector();
    } else if (token.is(Keyword::angle)) {
        parse_angle(p, p.next(), camera, items);
    } else if (token.is(Keyword::normal)) {
        camera.normal = parse_normal(p, p.next());
        camera.normal_location = p.location_of(token);
    } else if (projection_of(token)) {
        p.fail(token,
               fmt::format("the camera type '{}' must come first in the camera", p.word(token)));
    } else {
        return false;
    }
    return true;
}

// look_at turns direction, right and up toward the point about the sky vector, keeping their
// lengths and the handedness of up x direction against right.
void apply_look_at(Parser& p, Camera& camera, Vec3 look_at, const Token& look_at_token) {
    const double direction_length = length(camera.direction);
    const double up_length = length(camera.up);
    const double right_length = length(camera.right);
    const double handedness = dot(cross(camera.up, camera.direction), camera.right);
    Vec3 direction = look_at - camera.location;
    if (dot(direction, direction) < 1e-10)
        p.fail(look_at_token, "camera location and look_at must differ");
    direction = normalized(direction);
    Vec3 right = cross(camera.sky, direction);
    if (length(right) < 1e-10) right = camera.right;  // sky along the view: keep the old right
    right = normalized(right);
    camera.up = up_length * cross(direction, right);
    camera.direction = direction_length * direction;
    camera.right = (handedness > 0 ? right_length : -right_length) * right;
}

// The angle as each projection takes it: perspective and orthographic set the direction's
// length from it (as POV-Ray, 0 leaves it alone); the others keep it, with POV-Ray's defaults.
void apply_angle(Parser& p, Camera& camera, const CameraItems& items) {
    const bool planar = camera.projection == CameraProjection::perspective ||
                        camera.projection == CameraProjection::orthographic;
    if (!planar) {
        const double default_angle = camera.projection == CameraProjection::spherical ? 360 : 90;
        camera.angle = items.angle.value_or(default_angle);
        if (camera.projection == CameraProjection::spherical)
            camera.vertical_angle = items.vertical_angle.value_or(camera.angle / 2);
        return;
    }
    if (!items.angle || *items.angle == 0) return;
    if (*items.angle >= 180)
        p.fail(items.angle_token,
               fmt::format("{} camera's angle must be smaller than 180 degrees, found {}",
                           camera.projection == CameraProjection::perspective ? "a perspective"
                                                                              : "an orthographic",
                           *items.angle));
    if (length(camera.direction) == 0)
        p.fail(items.angle_token, "the camera direction is zero: 'angle' cannot set its length");
    camera.angle = *items.angle;
    const double half_angle = *items.angle * kPi / 360.0;
    const double direction_length = length(camera.right) / std::tan(half_angle) / 2.0;
    camera.direction = direction_length * normalized(camera.direction);
}

// Orthographic without up or right, or with an angle: the area a perspective camera of the same
// vectors sees at the look_at point (POV-Ray's default look_at is the point <0,0,1>, whatever
// the location). Checked against POV-Ray 3.7 renders: location -10*z and no look_at gives a
// view 11 units high.
void apply_orthographic_size(Camera& camera, const CameraItems& items) {
    if (items.up_or_right_given && !items.angle_given) return;
    const double direction_length = length(camera.direction);
    if (direction_length == 0) return;
    const Vec3 look_at = items.look_at.value_or(Vec3{0, 0, 1});
    const double scale = length(look_at - camera.location) / direction_length;
    camera.right = scale * camera.right;
    camera.up = scale * camera.up;
}

void resolve_camera(Parser& p, Camera& camera, const CameraItems& items) {
    apply_angle(p, camera, items);
    if (items.look_at) apply_look_at(p, camera, *items.look_at, items.look_at_token);
    if (camera.projection == CameraProjection::orthographic) apply_orthographic_size(camera, items);
    transform_camera(camera, items.transform);
}

}  // namespace

CameraRef parse_camera(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto result = std::make_shared<Camera>();
    Camera& camera = *result;
    camera.statement = p.location_of(keyword);
    if (CameraRef declared; p.take_declared(declared)) {
        // As in POV-Ray, a declared camera takes transforms only: its other items were resolved
        // when it was declared.
        camera = *declared;
        camera.statement = p.location_of(keyword);
        Matrix4 transform;
        while (!p.peek_is(Symbol::rbrace))
            if (!p.parse_transform_item(transform))
                p.fail_identifier(p.peek(),
                                  fmt::format("a transform or '}}' to close 'camera' opened at "
                                              "{} (a declared camera takes transforms only)",
                                              p.location_of(open).str()));
        p.expect_close(keyword, open);
        transform_camera(camera, transform);
        return result;
    }
    parse_projection(p, camera);
    CameraItems items;
    while (!p.peek_is(Symbol::rbrace))
        if (!parse_camera_item(p, camera, items))
            p.fail_identifier(p.peek(), fmt::format("a camera keyword or '}}' to close 'camera' "
                                                    "opened at {}",
                                                    p.location_of(open).str()));
    p.expect_close(keyword, open);
    resolve_camera(p, camera, items);
    return result;
}

}  // namespace rayset::tracer
