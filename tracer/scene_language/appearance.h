// The appearance of surfaces and volumes as POV-Ray describes it: patterns, pigments, normals,
// finishes, textures, interiors and media, with POV-Ray's defaults. Plain data for the renderer;
// the grammar that fills it is grammar_appearance.cpp and its neighbours (grammar.h lists them).
//
// One Pattern description serves pigments, normals, textures, media densities and pattern
// functions, as in POV-Ray. Transforms live in the patterns: transforming a texture transforms
// the patterns of everything in it (transform_appearance).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/colour.h"
#include "tracer/scene_language/copy_on_write.h"
#include "tracer/scene_language/image_file.h"
#include "tracer/scene_language/source_location.h"
#include "tracer/scene_language/transform.h"
#include "tracer/scene_language/values.h"

namespace rayset::tracer {

// POV-Ray's five-component colour: filter and transmit are the fractions of light passing
// through, filtered by the colour or not.
struct Colour {
    double red = 0, green = 0, blue = 0, filter = 0, transmit = 0;
    Rgb rgb() const { return {red, green, blue}; }
};

// ---------------------------------------------------------------- patterns

// Every pattern of POV-Ray 3.7 (reference 3.4.7), and the bitmaps that act as patterns.
// `plain` is no pattern: a solid colour, a normal that perturbs nothing, a plain texture.
enum class PatternKind {
    plain,
    agate,
    aoi,
    average,
    boxed,
    bozo,
    brick,
    bumps,
    cells,
    checker,
    crackle,
    cubic,
    cylindrical,
    density_file,
    dents,
    facets,
    function,
    gradient,
    granite,
    hexagon,
    image_pattern,
    julia,
    leopard,
    mandel,
    marble,
    object,
    onion,
    pavement,
    pigment_pattern,
    planar,
    quilted,
    radial,
    ripples,
    slope,
    spherical,
    spiral1,
    spiral2,
    spotted,
    square,
    tiling,
    triangular,
    waves,
    wood,
    wrinkles,
    image_map,     // pigment { image_map { ... } }: the image's colours
    bump_map,      // normal { bump_map { ... } }: the image's brightness as height
    material_map,  // texture { material_map { ... } }: the image's index picks a texture
                   // (the last: the grammar goes through agate..material_map)
};
const char* pattern_name(PatternKind kind);  // POV-Ray's keyword: "checker", "image_map", ...

// Block patterns give whole numbers 0, 1, ... N-1 that pick an entry of their list; the
// others give a value in [0, 1] looked up in a map. Lists hold N entries.
int list_size(PatternKind kind);  // 0: not a block pattern

// How a pattern's value is shaped before a map is looked up (reference 3.4.7.5.3).
enum class Waveform { ramp, triangle, sine, scallop, cubic, poly };

// POV-Ray's turbulence: `octaves` steps of DNoise, each `omega` times the size and `lambda`
// times the frequency of the one before.
struct Turbulence {
    Vec3 amount;  // per axis; zero: none
    int octaves = 6;
    double omega = 0.5;
    double lambda = 2.0;
};

// A warp { ... } or a transform, in the order written (reference 3.4.7.5.5).
struct Warp {
    enum class Kind {
        transform,
        turbulence,
        black_hole,
        repeat,
        cylindrical,
        spherical,
        toroidal,
        planar,
        cubic
    };
    Kind kind = Kind::transform;
    SourceLocation location;  // the warp keyword (transforms: none)
    // transform: from the pattern's space to the space it is placed in, composed from
    // consecutive translate/rotate/scale/matrix/transform statements.
    Matrix4 transform;
    Turbulence turbulence;  // turbulence
    // black_hole <centre>, radius
    Vec3 centre;
    double radius = 0;
    double strength = 1.0;
    double falloff = 2.0;
    bool inverse = false;
    int black_hole_type = 0;
    Vec3 black_hole_repeat;      // zero per axis: no repeat along it
    Vec3 black_hole_turbulence;  // random offset of each repeated black hole
    // repeat <direction> (one non-zero axis: the repeat width along it)
    Vec3 repeat;
    Vec3 offset;  // added at each repetition
    Vec3 flip;    // non-zero per axis: mirror every other copy along it
    // cylindrical, spherical, toroidal
    Vec3 orientation{0, 0, 1};
    double distance_exponent = 0;  // dist_exp
    double major_radius = 1;       // toroidal
    // planar [<normal>, distance]: the slice of the pattern taken and extruded along z
    Vec3 plane_normal{0, 0, 1};
    double plane_distance = 0;
};

// An image file or a function image for image_map, bump_map, material_map and image_pattern
// (reference 3.4.7.6 and 3.4.7.7).
struct ImageMap {
    std::string file_type;  // "png", "gif", "tga", ... as written; "function": a function image;
                            // empty: none written (POV-Ray takes the output file type)
    std::string path;       // resolved file; empty for a function image
    FunctionRef function;   // function image: a float, pattern or pigment function over [0,1]^2
    int function_width = 0, function_height = 0;
    bool gamma_given = false;
    bool gamma_srgb = false;  // gamma srgb
    double gamma = 1.0;       // gamma GAMMA (when given and not srgb)
    bool premultiplied_given = false;
    bool premultiplied = false;
    int map_type = 0;     // 0 planar, 1 spherical, 2 cylindrical, 5 torus
    bool once = false;    // no tiling outside the unit square
    int interpolate = 0;  // 0 none, 2 bilinear, 3 bicubic, 4 normalised distance
    // image_map: filter/transmit of palette entries, or of all (index -1) when `all`.
    struct PaletteAmount {
        int index = -1;  // -1: all
        double amount = 0;
    };
    std::vector<PaletteAmount> filter, transmit;
    bool use_alpha = false;   // image_pattern: the alpha channel as the value
    bool use_index = false;   // bump_map: palette index instead of brightness
    SourceLocation location;  // the image_map / bump_map / ... keyword
    // The file's pixels, read while parsing (null for a function image).
    std::shared_ptr<const ImagePixels> pixels;
    // Each pixel's colour (rows from the top) in the scene's colour numbers: decoded with the
    // file's gamma or the one written, encoded again with the scene's assumed_gamma as it was
    // when the image was read; alpha as transmit; `filter all` and `transmit all` added.
    std::shared_ptr<const std::vector<Colour>> colours;
};

struct CrackleParameters {
    Vec3 form{-1, 1, 0};  // weights of the distances to the 1st, 2nd and 3rd nearest points
    double metric = 2;    // Minkowski exponent of the distance
    double offset = 0;
    bool solid = false;  // one value per cell
};

// mandel, julia, and magnet 1/2 of either (reference 3.4.7.1.11).
struct FractalParameters {
    int magnet = 0;                              // 0: not a magnet fractal; 1 or 2
    double julia_real = 0, julia_imaginary = 0;  // julia's complex parameter
    int iterations = 0;
    int exponent = 2;  // mandel and julia: 2..33
    int exterior_type = 1;
    double exterior_factor = 1;
    int interior_type = 0;
    double interior_factor = 1;
};

struct SlopeParameters {
    Vec3 direction;         // slope { <direction> }: value 1 where the normal points along it
    bool point_at = false;  // slope { point_at <point> }: `direction` is the point
    double low_slope = 0, high_slope = 1;  // the slope range mapped to [0, 1]
    bool altitude_given = false;
    Vec3 altitude;  // weighted with the slope by the two vectors' lengths
    double low_altitude = 0, high_altitude = 1;
};

struct PavementParameters {
    int sides = 3;    // number_of_sides: 3 triangles, 4 squares, 6 hexagons
    int tiles = 1;    // number_of_tiles
    int pattern = 1;  // which of the tilings of that many tiles
    int exterior = 0, interior = 0, form = 0;  // how corners are drawn (0, 1, 2; form 3 squares)
};

// A pattern with everything that modifies it. Fields for other kinds keep their defaults.
struct Pattern {
    PatternKind kind = PatternKind::plain;
    SourceLocation location;  // the pattern's keyword (plain: none)

    Vec3 gradient{1, 0, 0};         // gradient <orientation>
    double agate_turbulence = 1.0;  // agate_turb
    Vec3 brick_size{8, 3, 4.5};     // brick_size
    double mortar = 0.5;            // mortar
    CrackleParameters crackle;      // crackle (metric also facets')
    double facets_coords = 0;       // facets coords SCALE (0: not given)
    double facets_size = 0.1;       // facets size FACTOR
    FractalParameters fractal;      // julia, mandel
    double quilted_control0 = 1, quilted_control1 = 1;
    SlopeParameters slope;  // slope { ... }
    int spiral_arms = 0;    // spiral1 N, spiral2 N
    int tiling = 1;         // tiling N (1..27)
    PavementParameters pavement;
    std::string density_file;               // density_file df3 "FILE": resolved path
    int interpolate = 0;                    // density_file: 0 none, 1 trilinear, 2 tricubic
    FunctionRef function;                   // function { ... }: a float function of x, y, z
    ObjectRef object;                       // object { OBJECT }: inside (1) or outside (0)
    PigmentRef pigment;                     // pigment_pattern { ... }: the pigment's grey value
    std::shared_ptr<const ImageMap> image;  // image_map, bump_map, material_map, image_pattern

    Waveform waveform = Waveform::ramp;  // marble, wood, spiral1 and spiral2 set triangle
    double poly_exponent = 1;            // poly_wave EXPONENT
    // value' = fmod(value * frequency + phase, 1.00001) (+1 when negative); frequency 0: none.
    // Block patterns take them only when frequency is written (POV-Ray 3.7's behaviour).
    double frequency = 1;
    bool frequency_written = false;
    double phase = 0;
    // Classic turbulence: applied before every warp and transform; agate, marble, wood,
    // spiral1 and spiral2 use it in their own way (reference 3.4.7.5.5.9).
    Turbulence turbulence;
    // Warps and transforms in the order written. A point is taken through them from the last
    // to the first (each undone), then through the classic turbulence, then the pattern.
    std::vector<Warp> warps;
    // 1, 2 or 3: as written, else global_settings' where the pattern was written (noise.h)
    int noise_generator = 0;
    bool uv_mapping = false;  // evaluated at the surface's <u, v, 0>
};

// ---------------------------------------------------------------- maps and lists

enum class BlendMapKind { colour, pigment, normal, slope, texture, density };

// One entry of a map, or one item of a block pattern's list. Only the field of the map's
// kind is used.
struct BlendMapEntry {
    double value = 0;    // the pattern value it stands at (a list's index; average: weight)
    Colour colour;       // colour_map; a colour in a pigment or density list
    PigmentRef pigment;  // pigment_map; density_map (densities are pigment-like)
    NormalRef normal;    // normal_map
    TextureRef texture;  // texture_map (may be layered)
    double height = 0, slope = 0;  // slope_map <height, slope>
};

// color_map, pigment_map, normal_map, slope_map, texture_map, density_map, or the list after
// a block pattern (entries at 0, 1, ... N-1). Entries stay as written (POV-Ray sorts nothing).
struct BlendMap {
    BlendMapKind kind = BlendMapKind::colour;
    std::vector<BlendMapEntry> entries;
};
using BlendMapPointer = std::shared_ptr<const BlendMap>;

// POV-Ray's built-in colour map or list of a pattern, used when a pigment or density gives
// none (reference 3.4.7: agate, bozo, brick, checker, cubic, hexagon, mandel, julia, marble,
// object, radial, square, triangular, wood); every other pattern goes from black to white.
const BlendMap& builtin_colour_map(PatternKind kind);

// ---------------------------------------------------------------- pigments and normals

// A pigment, and a media density (DensityRef): a solid colour, or a pattern with a map.
struct Pigment {
    CopyOnWrite<Pattern> pattern;
    Colour colour;        // plain: the colour (POV-Ray's default pigment is black)
    BlendMapPointer map;  // colour_map, pigment_map or list (density: density_map or list);
                          // null: builtin_colour_map(pattern.kind)
    bool quick_colour_given = false;
    Colour quick_colour;      // quick_color: for POV-Ray's low-quality previews
    SourceLocation location;  // the pigment (density, map entry) where it was last written
};

// Reference 3.4.6.2.
struct Normal {
    CopyOnWrite<Pattern> pattern;  // plain: no perturbation
    double amount = 0.5;           // the float after the pattern, or bump_size
    BlendMapPointer map;           // normal_map or normal list, or slope_map
    double accuracy = 0.02;        // step of the slope estimate of non-bump patterns
    bool no_bump_scale = false;    // scaling does not change the bump depth
    SourceLocation location;
};

// ---------------------------------------------------------------- finish

// POV-Ray 3.7 finish keywords with POV-Ray's defaults (reference 3.4.6.3).
struct Finish {
    Rgb ambient{0.1, 0.1, 0.1};
    Rgb emission{0, 0, 0};
    double diffuse = 0.6;
    bool diffuse_albedo = false;  // diffuse albedo A: A is total rather than peak reflectance
    double diffuse_back = 0;      // diffuse A, B: illumination from the back side
    double brilliance = 1.0;
    double crand = 0;  // random darkening of diffuse light
    double specular = 0;
    bool specular_albedo = false;
    double roughness = 0.05;
    double phong = 0;
    bool phong_albedo = false;
    double phong_size = 40;
    double metallic = 0;          // highlights take the pigment's colour
    Rgb reflection_min{0, 0, 0};  // `reflection X` sets both; `reflection { min, max }` each
    Rgb reflection_max{0, 0, 0};
    bool reflection_fresnel = false;
    double reflection_falloff = 1;
    double reflection_exponent = 1;  // reflection { exponent E } or reflection_exponent E
    double reflection_metallic = 0;  // reflection { metallic M }: reflection tinted by the pigment
    bool conserve_energy = false;
    // irid { amount thickness T turbulence U } (microns)
    double irid_amount = 0;
    double irid_thickness = 0;
    double irid_turbulence = 0;
    bool subsurface = false;  // subsurface { translucency COLOUR }
    Rgb translucency{0, 0, 0};
    // Interior items POV-Ray still takes in a finish (with a warning) and gives to the
    // object's interior: 0 when not written.
    double legacy_ior = 0;
    double legacy_refraction = 0;
    double legacy_caustics = 0;
    SourceLocation location;  // the finish block where it was last written
};

// ---------------------------------------------------------------- textures

// Reference 3.4.6: plain (pigment, normal, finish), patterned (a pattern over a texture_map or
// a texture list; tiles are a checker over two textures; material_map an image's index over a
// list), or layered (several textures, each over the ones below).
struct Texture {
    enum class Kind { plain, patterned, layered };
    Kind kind = Kind::plain;
    // plain
    Pigment pigment;
    NormalRef normal;  // null: none
    CopyOnWrite<Finish> finish;
    // patterned
    CopyOnWrite<Pattern> pattern;
    BlendMapPointer map;  // texture_map or texture list
    // layered: bottom first; each layer plain (POV-Ray allows no patterned layer)
    std::vector<TextureRef> layers;
    SourceLocation location;  // the texture keyword
};

// ---------------------------------------------------------------- interior and media

struct Media {
    int method = 3;  // sampling method 1, 2 or 3
    int intervals = 1;
    int samples_min = 1, samples_max = 1;
    double confidence = 0.9;
    double variance = 1.0 / 128;
    double ratio = 0.9;
    double jitter = 0;
    int aa_level = 3;
    double aa_threshold = 0.1;
    Rgb absorption{0, 0, 0};
    Rgb emission{0, 0, 0};
    int scattering_type = 0;  // 0: no scattering; 1 isotropic, 2 Mie haze, 3 Mie murky,
                              // 4 Rayleigh, 5 Henyey-Greenstein
    Rgb scattering{0, 0, 0};
    double eccentricity = 0;  // Henyey-Greenstein
    double extinction = 1;
    std::vector<DensityRef> densities;  // multiplied together; none: density 1 everywhere
    SourceLocation location;
};

struct Interior {
    double ior = 1.0;
    double caustics = 0;
    double dispersion = 1.0;  // ratio of the ior for violet to red
    int dispersion_samples = 7;
    double fade_distance = 0;  // 0: no attenuation
    double fade_power = 0;
    Rgb fade_colour{0, 0, 0};
    std::vector<MediaRef> media;  // added together
    SourceLocation location;
};

// ---------------------------------------------------------------- what objects carry

// What an object's own modifiers say about its appearance (texture, pigment, normal, finish,
// interior, material, interior_texture), in the coordinates the object is placed in: its
// textures and interior follow the object's transforms written after them
// (transform_appearance). Once the tree is flattened (ObjectInstance), what it ends up with
// in world coordinates: its own, else the nearest enclosing union's, else the #default
// texture of the moment it was added to the scene (inherit_appearance,
// scene_default_appearance in grammar.h).
struct ObjectAppearance {
    TextureRef texture;           // null: none yet; may be layered
    TextureRef interior_texture;  // for the inside surface; null: the texture
    InteriorRef interior;         // null: none
};

// POV-Ray's `material { texture interior_texture interior transforms }`.
struct TextureAndInterior {
    TextureRef texture;
    TextureRef interior_texture;
    InteriorRef interior;
};

// POV-Ray's transform of textures, interiors and media: the transform applied to every
// pattern in them (copies; shared items are not changed).
void transform_texture(Texture& texture, const Matrix4& transform);
void transform_pigment(Pigment& pigment, const Matrix4& transform);
void transform_normal(Normal& normal, const Matrix4& transform);
void transform_interior(Interior& interior, const Matrix4& transform);
void transform_media(Media& media, const Matrix4& transform);
void transform_pattern(Pattern& pattern, const Matrix4& transform);
// A copy of `map` with `transform` applied to every pigment, normal, texture or density in it.
BlendMapPointer transformed_map(const BlendMapPointer& map, const Matrix4& transform);
// An object's transform after its appearance modifiers: POV-Ray moves its textures and
// interior with it.
void transform_appearance(ObjectAppearance& appearance, const Matrix4& transform);

}  // namespace rayset::tracer
