// Mafia .4ds (version 29) reader. Layout as documented publicly (the 4ds
// documentation on readthedocs, the Max4dsTools and Blender add-on parsers);
// checked against every file in shared/scenes/4ds, which all parse to their
// last byte. All multi-byte values are little-endian; strings are a u8
// length and that many bytes of Windows-1250 text.
//
//   file     : "4DS\0", u16 version, u64 timestamp (FILETIME),
//              u16 materialCount, MATERIAL[], u16 frameCount, FRAME[],
//              u8 allow5dsAnimation
//   MATERIAL : u32 flags, vec3 ambient, vec3 diffuse, vec3 emission, f32 opacity,
//              [ENV_MAP: f32 envRatio, str envMap], str diffuseMap,
//              [diffuseMap non-empty, ALPHA_MAP and not IMAGE_ALPHA: str alphaMap],
//              [ANIMATED_DIFFUSE: u32 frames, u16, u32 period, u32, u32]
//   FRAME    : u8 type, [type 1: u8 visualType, u16 renderFlags], u16 parent
//              (1-based, 0 = none), vec3 position, vec3 scale, quat (w, x, y, z),
//              u8 cullingFlags, str name, str parameters, then per type data.
#include "lpv/importers/FourDsReader.h"

#include "ByteReader.h"
#include "TextEncoding.h"
#include "TextureResolver.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <new>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace lpv::importers {

namespace {

namespace fs = std::filesystem;
using scene::ErrorCode;

constexpr std::array<std::uint8_t, 4> kMagic = {'4', 'D', 'S', 0};

// Material flag bits (the u32 at the start of every material).
namespace MaterialFlag {
constexpr std::uint32_t EnvironmentMap = 0x00080000;
constexpr std::uint32_t ImageAlpha = 0x01000000; // alpha from the diffuse map itself: no alpha map name
constexpr std::uint32_t AnimatedDiffuse = 0x04000000;
constexpr std::uint32_t Colored = 0x08000000; // diffuse colour used although a diffuse map is set
constexpr std::uint32_t TwoSided = 0x10000000;
constexpr std::uint32_t ColorKey = 0x20000000; // first palette colour of an 8-bit map is transparent
constexpr std::uint32_t AlphaMap = 0x40000000;
constexpr std::uint32_t AdditiveMixing = 0x80000000;
} // namespace MaterialFlag

namespace FrameType {
constexpr std::uint8_t Visual = 1;
constexpr std::uint8_t Sector = 5;
constexpr std::uint8_t Dummy = 6;
constexpr std::uint8_t Target = 7;
constexpr std::uint8_t Joint = 10;
constexpr std::uint8_t Occluder = 12;
} // namespace FrameType

namespace VisualType {
constexpr std::uint8_t Standard = 0;
constexpr std::uint8_t LitObject = 1;
constexpr std::uint8_t SingleMesh = 2;
constexpr std::uint8_t SingleMorph = 3;
constexpr std::uint8_t Billboard = 4;
constexpr std::uint8_t Morph = 5;
constexpr std::uint8_t Glow = 6;
constexpr std::uint8_t Mirror = 8;
} // namespace VisualType

// Record sizes in bytes.
constexpr std::uint64_t kVertexSize = 32; // position, normal, uv
constexpr std::uint64_t kFaceSize = 6;    // three u16 indices
constexpr std::uint64_t kVec3Size = 12;
constexpr std::uint64_t kBoxSize = 24;
constexpr std::uint64_t kMatrixSize = 64;
// The smallest possible records, to reject counts the file cannot hold.
constexpr std::uint64_t kMinMaterialSize = 4 + 10 * 4 + 1;
constexpr std::uint64_t kMinFrameSize = 1 + 2 + 12 + 12 + 16 + 1 + 1 + 1;

const char* frameTypeName(std::uint8_t type) {
    static constexpr std::array<const char*, 16> names = {
        "unknown", "visual", "light", "camera", "sound",    "sector", "dummy", "target",
        "user",    "model",  "joint", "volume", "occluder", "scene",  "area",  "landscape"};
    return type < names.size() ? names[type] : "unknown";
}

const char* visualTypeName(std::uint8_t type) {
    static constexpr std::array<const char*, 12> names = {
        "standard mesh", "lit mesh",  "skinned mesh", "skinned morph", "billboard", "morph",
        "glow",          "projector", "mirror",       "emitter",       "shadow",    "land patch"};
    return type < names.size() ? names[type] : "unknown";
}

struct RawMaterial {
    std::uint32_t flags = 0;
    glm::vec3 diffuse{0.0f};
    glm::vec3 emission{0.0f};
    float opacity = 1.0f;
    float envRatio = 0.0f;
    std::string envMap, diffuseMap, alphaMap; // as stored (UTF-8)
    std::uint32_t animationFrames = 0;
};

struct RawVertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec2 uv;
};

struct RawFaceGroup {
    std::vector<std::array<std::uint16_t, 3>> faces;
    std::uint16_t material = 0; // 1-based, 0 = none
};

struct RawLod {
    float distance = 0.0f; // the camera distance from which this LOD is used
    std::vector<RawVertex> vertices;
    std::vector<RawFaceGroup> groups;
};

bool hasFaces(const RawLod& lod) {
    return std::any_of(lod.groups.begin(), lod.groups.end(),
                       [](const RawFaceGroup& g) { return !g.faces.empty(); });
}

struct RawFrame {
    std::string name;
    std::uint8_t type = 0;
    std::uint8_t visual = 0;
    std::uint16_t parent = 0; // 1-based, 0 = none
    std::size_t parentOffset = 0;
    std::uint16_t instanceOf = 0; // 1-based frame whose mesh this one reuses
    std::size_t instanceOffset = 0;
    scene::Transform transform;
    std::optional<RawLod> lod0;
    std::vector<RawLod> furtherLods; // LOD 1..n: stored in the scene, not drawn
};

std::string frameLabel(std::size_t index, const std::string& name) {
    return "frame #" + std::to_string(index + 1) + " '" + name + "'";
}

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Coordinates. Mafia is a Direct3D game: left-handed, Y up, front faces wound
// clockwise. We are right-handed, Y up, front faces counter-clockwise. We
// mirror X: position (x, y, z) -> (-x, y, z), the same for normals, and we
// reverse the winding so the front side stays the side the normals point to.
// X (not Z) because it is the mirror the data was made with: the shipped
// sibenik.4ds is Dabrovic's right-handed sibenik.obj with X negated, so after
// our import it is the OBJ moved by (1.295, 14.364, 0), same orientation. In
// the file, the winding agrees with the stored normals for 72,458 of 72,524
// Sibenik faces (a left-handed, clockwise file does that), so reversing it
// together with the mirror keeps every face's front side.
glm::vec3 convertPosition(const glm::vec3& p) {
    return {-p.x, p.y, p.z};
}
glm::vec3 convertDirection(const glm::vec3& d) {
    return convertPosition(d);
}

// Rotations. The file stores the quaternion as (w, x, y, z) and rotates with
// the ordinary formula: the thesis engine composes T * mat4_cast(quat(w, x, y,
// z)) * S, and with it the sun quad of denjasno2.4ds lies across the line to
// the scene origin (with the conjugate, which some Blender add-ons assume, it
// would be edge-on). Mirroring X turns a rotation about axis a by angle t into
// one about (-ax, ay, az) by -t: (w, x, y, z) -> (w, x, -y, -z).
// Some files store unnormalised quaternions (white_interier.4ds: w = 0.707).
glm::quat convertRotation(float w, float x, float y, float z) {
    const float length = std::sqrt(w * w + x * x + y * y + z * z);
    if (!(length > 1e-6f))
        return glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
    return glm::quat(w / length, x / length, -y / length, -z / length);
}

// Mafia's V runs down the image (Direct3D); we use V running up from the
// bottom row (OpenGL, OBJ), so v -> 1 - v. Checked against sibenik.obj:
// 86,992 of the 87,628 vertices found in both have exactly this relation.
glm::vec2 convertUv(const glm::vec2& uv) {
    return {uv.x, 1.0f - uv.y};
}

class FourDsParser {
  public:
    FourDsParser(std::span<const std::uint8_t> bytes, const fs::path& file, const ImportOptions& options)
        : r_(bytes), file_(file), resolver_(textureFoldersFor(file, options.textureSearchPaths)),
          roots_(importReadRoots(file, options)) {}

    ImportResult parse() {
        readHeader();
        readMaterials();
        readFrames();
        linkHierarchy();
        buildScene();
        return std::move(result_);
    }

  private:
    void warn(const std::string& message) { result_.warnings.push_back(file_.string() + ": " + message); }

    [[noreturn]] void fail(ErrorCode code, std::size_t offset, std::string message) const {
        throw FormatError(code, offset, std::move(message));
    }

    std::string readString(std::string_view what) {
        const std::uint8_t length = r_.u8(what);
        auto text = r_.bytes(length, what);
        // Some exporters count a terminating NUL in the length.
        while (!text.empty() && text.back() == 0)
            text = text.first(text.size() - 1);
        return windows1250ToUtf8(text);
    }

    void readHeader() {
        r_.skip(kMagic.size(), "signature"); // checked by readFourDs
        const std::size_t versionOffset = r_.offset();
        const std::uint16_t version = r_.u16("version");
        if (version != kFourDsVersion) {
            const std::string found = "4ds version " + std::to_string(version);
            if (version > kFourDsVersion)
                fail(ErrorCode::NewerVersion, versionOffset,
                     found +
                         " is not supported (41 is Hidden & Dangerous 2, 42 Chameleon); this reader reads " +
                         "version 29 (Mafia)");
            fail(ErrorCode::UnknownFormat, versionOffset,
                 found + " is not supported; this reader reads version 29 (Mafia)");
        }
        r_.u64("timestamp");
    }

    void readMaterials() {
        const std::uint16_t count = r_.u16("material count");
        r_.requireArray(count, kMinMaterialSize, "materials");
        materials_.reserve(count);
        for (std::size_t i = 0; i < count; ++i)
            materials_.push_back(readMaterial(i));
    }

    RawMaterial readMaterial(std::size_t index) {
        const std::size_t start = r_.offset();
        RawMaterial m;
        m.flags = r_.u32("material flags");
        r_.vec3("ambient colour"); // no place for it in our model: ambient light comes from the LPV
        m.diffuse = r_.vec3("diffuse colour");
        m.emission = r_.vec3("emission colour");
        m.opacity = r_.f32("opacity");
        if (!finite(m.diffuse) || !finite(m.emission) || !std::isfinite(m.opacity))
            fail(ErrorCode::NonFinite, start,
                 "material " + std::to_string(index + 1) +
                     " has a colour or opacity that is not a finite number");
        if (m.flags & MaterialFlag::EnvironmentMap) {
            const std::size_t ratioOffset = r_.offset();
            m.envRatio = r_.f32("environment map ratio");
            // NaN would pass std::clamp into the glossiness (found by fuzz_4ds).
            if (!std::isfinite(m.envRatio))
                fail(ErrorCode::NonFinite, ratioOffset,
                     "material " + std::to_string(index + 1) +
                         " has an environment map ratio that is not a finite number");
            m.envMap = readString("environment map name");
        }
        m.diffuseMap = readString("diffuse map name");
        if (!m.diffuseMap.empty() && (m.flags & MaterialFlag::AlphaMap) &&
            !(m.flags & MaterialFlag::ImageAlpha))
            m.alphaMap = readString("alpha map name");
        if (m.flags & MaterialFlag::AnimatedDiffuse) {
            m.animationFrames = r_.u32("animation frame count");
            r_.skip(2 + 4 + 4 + 4, "texture animation");
        }
        return m;
    }

    void readFrames() {
        frameCount_ = r_.u16("frame count");
        r_.requireArray(frameCount_, kMinFrameSize, "frames");
        frames_.reserve(frameCount_);
        for (std::size_t i = 0; i < frameCount_; ++i) {
            if (!readFrame(i)) {
                if (i + 1 < frameCount_)
                    warn("the remaining " + std::to_string(frameCount_ - i - 1) + " of " +
                         std::to_string(frameCount_) + " frames were not read");
                return;
            }
        }
        r_.u8("5ds animation flag");
        if (!r_.atEnd())
            warn(std::to_string(r_.remaining()) + " byte(s) after the end of the model were ignored");
    }

    // Reads one frame; false when its type has an unknown layout, which ends
    // the frame list (there is no length field to skip it by).
    bool readFrame(std::size_t index) {
        RawFrame& f = frames_.emplace_back();
        f.type = r_.u8("frame type");
        if (f.type == FrameType::Visual) {
            f.visual = r_.u8("visual type");
            r_.u16("render flags");
        }
        f.parentOffset = r_.offset();
        f.parent = r_.u16("parent index");
        const std::size_t transformOffset = r_.offset();
        const glm::vec3 position = r_.vec3("frame position");
        const glm::vec3 scale = r_.vec3("frame scale");
        const float qw = r_.f32("frame rotation");
        const float qx = r_.f32("frame rotation");
        const float qy = r_.f32("frame rotation");
        const float qz = r_.f32("frame rotation");
        r_.u8("culling flags");
        f.name = readString("frame name");
        readString("frame parameters");
        if (!finite(position) || !finite(scale) || !finite(glm::vec3(qx, qy, qz)) || !std::isfinite(qw))
            fail(ErrorCode::NonFinite, transformOffset,
                 frameLabel(index, f.name) + " has a transform that is not made of finite numbers");
        f.transform.translation = convertPosition(position);
        f.transform.rotation = convertRotation(qw, qx, qy, qz);
        f.transform.scale = scale;
        return f.type == FrameType::Visual ? readVisual(index, f) : readOtherFrame(index, f);
    }

    bool readVisual(std::size_t index, RawFrame& f) {
        const std::string label = frameLabel(index, f.name);
        const std::string kind =
            std::string("visual type ") + std::to_string(f.visual) + " (" + visualTypeName(f.visual) + ")";
        switch (f.visual) {
        case VisualType::Standard:
        case VisualType::LitObject:
            readStandardMesh(index, f);
            return true;
        case VisualType::SingleMesh:
            skipSkin(readStandardMesh(index, f));
            warn(label + ": " + kind + ": imported in its bind pose; bones and weights were dropped");
            return true;
        case VisualType::SingleMorph:
            skipSkin(readStandardMesh(index, f));
            skipMorph();
            warn(label + ": " + kind +
                 ": imported in its rest pose; bones, weights and morph targets were dropped");
            return true;
        case VisualType::Billboard:
            readStandardMesh(index, f);
            r_.skip(4 + 1, "billboard axis and mode");
            warn(label + ": " + kind + ": imported as a static mesh; it no longer turns to the camera");
            return true;
        case VisualType::Morph:
            readStandardMesh(index, f);
            skipMorph();
            warn(label + ": " + kind + ": imported in its rest pose; morph targets were dropped");
            return true;
        case VisualType::Glow: {
            const std::uint8_t flares = r_.u8("glow flare count");
            r_.skip(std::uint64_t(flares) * 6, "glow flares");
            warn(label + ": " + kind + " with " + std::to_string(flares) +
                 " flare(s) skipped: it has no geometry");
            return true;
        }
        case VisualType::Mirror:
            skipMirror();
            warn(label + ": " + kind + " skipped: mirrors are not supported");
            return true;
        default:
            warn(label + ": " + kind + " has a layout this reader does not know; reading stopped there");
            return false;
        }
    }

    bool readOtherFrame(std::size_t index, RawFrame& f) {
        const std::string label = frameLabel(index, f.name);
        const std::string kind =
            std::string("frame type ") + std::to_string(f.type) + " (" + frameTypeName(f.type) + ")";
        switch (f.type) {
        case FrameType::Dummy:
            r_.skip(kBoxSize, "dummy bounding box"); // a plain node: nothing is lost
            return true;
        case FrameType::Sector:
            skipSector();
            warn(label + ": " + kind + ": kept as a node; its visibility volume and portals were skipped");
            return true;
        case FrameType::Target: {
            r_.skip(2, "target flags");
            const std::uint8_t links = r_.u8("target link count");
            r_.skip(std::uint64_t(links) * 2, "target links");
            warn(label + ": " + kind + ": kept as a node; its look-at links were skipped");
            return true;
        }
        case FrameType::Joint:
            r_.skip(kMatrixSize + 4, "joint matrix and bone id");
            warn(label + ": " + kind + ": kept as a node; its bone data was skipped");
            return true;
        case FrameType::Occluder:
            skipTriangleSoup("occluder");
            warn(label + ": " + kind + ": kept as a node; its occlusion mesh was skipped");
            return true;
        default:
            warn(label + ": " + kind + " has a layout this reader does not know; reading stopped there");
            return false;
        }
    }

    // Returns the number of LODs (the skin that may follow has one record per LOD).
    std::size_t readStandardMesh(std::size_t index, RawFrame& f) {
        f.instanceOffset = r_.offset();
        f.instanceOf = r_.u16("mesh instance index");
        if (f.instanceOf != 0) {
            if (f.instanceOf > frameCount_)
                fail(ErrorCode::IndexOutOfRange, f.instanceOffset,
                     frameLabel(index, f.name) + " instances frame #" + std::to_string(f.instanceOf) +
                         " but the file has " + std::to_string(frameCount_) + " frames");
            return 0;
        }
        const std::uint8_t lodCount = r_.u8("LOD count");
        for (std::size_t lod = 0; lod < lodCount; ++lod) {
            RawLod data = readLod(index, f.name, lod);
            if (lod == 0)
                f.lod0 = std::move(data);
            else
                f.furtherLods.push_back(std::move(data));
        }
        if (lodCount == 0)
            warn(frameLabel(index, f.name) + ": the mesh has no LOD; nothing to import");
        return lodCount;
    }

    RawLod readLod(std::size_t index, const std::string& frameName, std::size_t lod) {
        const std::string where = "LOD " + std::to_string(lod) + " of " + frameLabel(index, frameName);
        RawLod out;
        out.distance = r_.f32("LOD distance");
        const std::uint16_t vertexCount = r_.u16("vertex count");
        r_.requireArray(vertexCount, kVertexSize, "vertices of " + where);
        out.vertices.reserve(vertexCount);
        for (std::size_t v = 0; v < vertexCount; ++v) {
            const std::size_t at = r_.offset();
            RawVertex vx;
            vx.position = r_.vec3("vertex position");
            vx.normal = r_.vec3("vertex normal");
            vx.uv.x = r_.f32("vertex uv");
            vx.uv.y = r_.f32("vertex uv");
            if (!finite(vx.position) || !finite(vx.normal) || !std::isfinite(vx.uv.x) ||
                !std::isfinite(vx.uv.y))
                fail(ErrorCode::NonFinite, at,
                     "vertex " + std::to_string(v) + " of " + where + " is not made of finite numbers");
            out.vertices.push_back(vx);
        }
        const std::uint8_t groupCount = r_.u8("face group count");
        out.groups.reserve(groupCount);
        for (std::size_t g = 0; g < groupCount; ++g)
            out.groups.push_back(readFaceGroup(where, g, vertexCount));
        return out;
    }

    RawFaceGroup readFaceGroup(const std::string& where, std::size_t group, std::size_t vertexCount) {
        RawFaceGroup out;
        const std::uint16_t faceCount = r_.u16("face count");
        r_.requireArray(faceCount, kFaceSize, "faces of group " + std::to_string(group) + " of " + where);
        out.faces.reserve(faceCount);
        for (std::size_t i = 0; i < faceCount; ++i) {
            const std::size_t at = r_.offset();
            std::array<std::uint16_t, 3> face{};
            for (auto& corner : face)
                corner = r_.u16("face index");
            for (const std::uint16_t corner : face)
                if (corner >= vertexCount)
                    fail(ErrorCode::IndexOutOfRange, at,
                         "face " + std::to_string(i) + " of group " + std::to_string(group) + " of " + where +
                             " uses vertex " + std::to_string(corner) + " but the LOD has " +
                             std::to_string(vertexCount) + " vertices");
            out.faces.push_back(face);
        }
        const std::size_t at = r_.offset();
        out.material = r_.u16("face group material");
        if (out.material > materials_.size())
            fail(ErrorCode::IndexOutOfRange, at,
                 "group " + std::to_string(group) + " of " + where + " uses material " +
                     std::to_string(out.material) + " but the file has " + std::to_string(materials_.size()) +
                     " materials");
        return out;
    }

    // Skinning records, one per LOD; Mafia layout (documented by Max4dsTools).
    void skipSkin(std::size_t lodCount) {
        for (std::size_t lod = 0; lod < lodCount; ++lod) {
            const std::uint8_t joints = r_.u8("skin joint count");
            r_.skip(4 + kBoxSize, "skin header");
            for (std::size_t j = 0; j < joints; ++j) {
                r_.skip(kMatrixSize + 4, "skin joint matrix");
                const std::uint32_t weights = r_.u32("skin weight count");
                r_.skip(4 + kBoxSize, "skin joint header");
                r_.requireArray(weights, 4, "skin weights");
                r_.skip(std::uint64_t(weights) * 4, "skin weights");
            }
        }
    }

    void skipMorph() {
        const std::uint8_t targets = r_.u8("morph target count");
        if (targets == 0)
            return;
        const std::uint8_t regions = r_.u8("morph region count");
        const std::uint8_t lods = r_.u8("morph LOD count");
        for (std::size_t i = 0; i < std::size_t(regions) * lods; ++i) {
            const std::uint16_t vertices = r_.u16("morph vertex count");
            r_.requireArray(std::uint64_t(vertices) * targets, 2 * kVec3Size, "morph vertices");
            r_.skip(std::uint64_t(vertices) * targets * 2 * kVec3Size, "morph vertices");
            if (vertices != 0)
                r_.skip(1, "morph region flag");
            r_.requireArray(vertices, 2, "morph vertex links");
            r_.skip(std::uint64_t(vertices) * 2, "morph vertex links");
        }
        r_.skip(kBoxSize + kVec3Size + 4, "morph bounds");
    }

    void skipMirror() {
        r_.skip(kBoxSize + kVec3Size + 4 + kMatrixSize + kVec3Size + 4, "mirror header");
        skipTriangleSoup("mirror");
    }

    void skipSector() {
        r_.skip(8, "sector flags");
        skipTriangleSoup("sector");
        r_.skip(kBoxSize, "sector bounding box");
        const std::uint8_t portals = r_.u8("portal count");
        for (std::size_t p = 0; p < portals; ++p) {
            const std::uint8_t vertices = r_.u8("portal vertex count");
            r_.skip(4 + 4 + 4 + kVec3Size + 4, "portal header");
            r_.skip(std::uint64_t(vertices) * kVec3Size, "portal vertices");
        }
    }

    // u32 vertex count, u32 face count, vec3 vertices, u16[3] faces.
    void skipTriangleSoup(const std::string& what) {
        const std::uint32_t vertices = r_.u32(what + " vertex count");
        const std::uint32_t faces = r_.u32(what + " face count");
        r_.requireArray(vertices, kVec3Size, what + " vertices");
        r_.skip(std::uint64_t(vertices) * kVec3Size, what + " vertices");
        r_.requireArray(faces, kFaceSize, what + " faces");
        r_.skip(std::uint64_t(faces) * kFaceSize, what + " faces");
    }

    // Parent indices point at any frame of the file; out of range or cyclic
    // ones are errors (a cycle has no world transform).
    void linkHierarchy() {
        parents_.assign(frames_.size(), -1);
        for (std::size_t i = 0; i < frames_.size(); ++i) {
            const RawFrame& f = frames_[i];
            if (f.parent == 0)
                continue;
            if (f.parent > frameCount_)
                fail(ErrorCode::IndexOutOfRange, f.parentOffset,
                     frameLabel(i, f.name) + " names parent #" + std::to_string(f.parent) +
                         " but the file has " + std::to_string(frameCount_) + " frames");
            if (f.parent > frames_.size()) {
                warn(frameLabel(i, f.name) + ": its parent #" + std::to_string(f.parent) +
                     " was not read; the frame was attached to the root");
                continue;
            }
            parents_[i] = int(f.parent) - 1;
        }
        rejectCycles();
    }

    void rejectCycles() const {
        // 0 = not visited, 1 = on the chain being walked, 2 = known to reach the root.
        std::vector<std::uint8_t> state(frames_.size(), 0);
        std::vector<std::size_t> chain;
        for (std::size_t start = 0; start < frames_.size(); ++start) {
            chain.clear();
            int at = int(start);
            while (at >= 0 && state[std::size_t(at)] == 0) {
                state[std::size_t(at)] = 1;
                chain.push_back(std::size_t(at));
                at = parents_[std::size_t(at)];
            }
            if (at >= 0 && state[std::size_t(at)] == 1) {
                const RawFrame& f = frames_[std::size_t(at)];
                fail(ErrorCode::InvalidValue, f.parentOffset,
                     frameLabel(std::size_t(at), f.name) +
                         " is its own ancestor: the parent indices form a cycle");
            }
            for (const std::size_t c : chain)
                state[c] = 2;
        }
    }

    void buildScene() {
        scene::Scene& s = result_.scene;
        std::vector<int> meshOfFrame(frames_.size(), -1);
        s.objects.reserve(frames_.size());
        for (std::size_t i = 0; i < frames_.size(); ++i) {
            RawFrame& f = frames_[i];
            scene::Object o;
            o.name = f.name;
            o.parent = parents_[i];
            o.transform = f.transform;
            if (f.lod0 && hasFaces(*f.lod0)) {
                meshOfFrame[i] = int(s.meshes.size());
                s.meshes.push_back(toSceneMesh(*f.lod0, f.name));
            } else if (f.lod0) {
                warn(frameLabel(i, f.name) + ": LOD 0 has no faces; no mesh was created");
            }
            f.lod0.reset();
            o.mesh = meshOfFrame[i];
            if (o.mesh >= 0)
                addFurtherLods(f, o);
            s.objects.push_back(std::move(o));
        }
        resolveInstances(meshOfFrame);
        buildMaterials();
        result_.stats.objects = s.objects.size();
        result_.stats.triangles = s.triangleCount(); // drawn objects: instances count, further LODs do not
        result_.stats.materials = s.materials.size();
        result_.stats.texturesFound = foundTextures_.size();
        result_.stats.texturesMissing = missingTextures_.size();
    }

    // LOD 1..n become meshes of their own that the object lists by distance;
    // only LOD 0 is drawn (and counted in the summary's triangles).
    void addFurtherLods(RawFrame& f, scene::Object& o) {
        scene::Scene& s = result_.scene;
        for (std::size_t k = 0; k < f.furtherLods.size(); ++k) {
            const RawLod& lod = f.furtherLods[k];
            if (!hasFaces(lod) || !std::isfinite(lod.distance))
                continue;
            o.lods.push_back({int(s.meshes.size()), std::max(lod.distance, 0.0f)});
            s.meshes.push_back(toSceneMesh(lod, f.name + " LOD " + std::to_string(k + 1)));
        }
        f.furtherLods.clear();
        std::stable_sort(o.lods.begin(), o.lods.end(),
                         [](const scene::LodLevel& a, const scene::LodLevel& b) { return a.distance < b.distance; });
    }

    // An instance reuses the mesh of another frame (Mafia's way to repeat a
    // prop); resolved in file order so an instance of an instance works.
    void resolveInstances(std::vector<int>& meshOfFrame) {
        for (std::size_t i = 0; i < frames_.size(); ++i) {
            const RawFrame& f = frames_[i];
            if (f.instanceOf == 0)
                continue;
            const std::size_t target = f.instanceOf - 1u;
            if (target < frames_.size() && meshOfFrame[target] >= 0) {
                meshOfFrame[i] = meshOfFrame[target];
                result_.scene.objects[i].mesh = meshOfFrame[i];
            } else {
                warn(frameLabel(i, f.name) + ": it instances frame #" + std::to_string(f.instanceOf) +
                     ", which has no mesh; the frame stays empty");
            }
        }
    }

    // File material k (1-based) is scene material k - 1; faces without a
    // material (k = 0) share one grey default appended after them.
    std::uint32_t sceneMaterialIndex(std::uint16_t fileMaterial) {
        if (fileMaterial != 0)
            return fileMaterial - 1u;
        usesDefaultMaterial_ = true;
        return std::uint32_t(materials_.size());
    }

    scene::Mesh toSceneMesh(const RawLod& lod, const std::string& name) {
        scene::Mesh m;
        m.name = name;
        m.positions.reserve(lod.vertices.size());
        m.normals.reserve(lod.vertices.size());
        m.uvs.reserve(lod.vertices.size());
        for (const RawVertex& v : lod.vertices) {
            m.positions.push_back(convertPosition(v.position));
            m.normals.push_back(convertDirection(v.normal));
            m.uvs.push_back(convertUv(v.uv));
        }
        for (const RawFaceGroup& g : lod.groups) {
            if (g.faces.empty())
                continue;
            scene::Submesh sub;
            sub.firstIndex = std::uint32_t(m.indices.size());
            sub.indexCount = std::uint32_t(3 * g.faces.size());
            sub.materialIndex = sceneMaterialIndex(g.material);
            for (const auto& face : g.faces) // reversed winding: see convertPosition
                m.indices.insert(m.indices.end(), {face[0], face[2], face[1]});
            m.submeshes.push_back(sub);
        }
        return m;
    }

    void buildMaterials() {
        std::vector<scene::Material>& out = result_.scene.materials;
        out.reserve(materials_.size() + 1);
        std::set<std::string> usedNames;
        for (std::size_t i = 0; i < materials_.size(); ++i)
            out.push_back(toSceneMaterial(materials_[i], i, usedNames));
        if (usesDefaultMaterial_) {
            scene::Material fallback;
            fallback.name = "4ds default";
            out.push_back(fallback);
        }
    }

    scene::Material toSceneMaterial(const RawMaterial& raw, std::size_t index,
                                    std::set<std::string>& usedNames) {
        scene::Material m;
        m.name = materialName(raw, index, usedNames);
        const std::string label = "material " + std::to_string(index + 1) + " '" + m.name + "'";
        const bool textured = !raw.diffuseMap.empty();
        // Mafia ignores the diffuse colour of a textured material unless it is
        // flagged COLORED; the texture alone gives the colour.
        m.diffuseColor = textured && !(raw.flags & MaterialFlag::Colored) ? glm::vec3(1.0f) : raw.diffuse;
        m.emissive = raw.emission;
        m.opacity = std::clamp(raw.opacity, 0.0f, 1.0f);
        m.twoSided = (raw.flags & MaterialFlag::TwoSided) != 0;
        m.additive = (raw.flags & MaterialFlag::AdditiveMixing) != 0;
        m.colorKey = (raw.flags & MaterialFlag::ColorKey) != 0;
        if (m.additive || !raw.alphaMap.empty() || m.opacity < 1.0f)
            m.alphaMode = scene::AlphaMode::Blend;
        else if (m.colorKey)
            m.alphaMode = scene::AlphaMode::Mask; // the key colour becomes alpha when the map is loaded
        if (textured)
            resolveDiffuse(raw, label, m);
        if (!raw.alphaMap.empty())
            m.alphaTexture = resolvedOrName(raw.alphaMap, "alpha map of " + label);
        if (raw.flags & MaterialFlag::EnvironmentMap) {
            // The environment map is Mafia's fake reflection; its strength is
            // also what our glossy LPV reflections need.
            m.environmentRatio = std::clamp(raw.envRatio, 0.0f, 1.0f);
            m.glossiness = m.environmentRatio;
            if (!raw.envMap.empty())
                m.environmentTexture = resolvedOrName(raw.envMap, "environment map of " + label);
        }
        if (raw.flags & MaterialFlag::AnimatedDiffuse)
            warn(label + ": texture animation (" + std::to_string(raw.animationFrames) +
                 " frames) is not supported; the first frame is used");
        return m;
    }

    void resolveDiffuse(const RawMaterial& raw, const std::string& label, scene::Material& m) {
        const std::optional<fs::path> diffuse = resolveTexture(raw.diffuseMap, "diffuse map of " + label);
        m.diffuseTexture = diffuse ? diffuse->string() : std::string(textureFileName(raw.diffuseMap));
        if (!diffuse)
            return;
        // The thesis convention: <name>_ddn (normal) and <name>_spec (specular)
        // beside the diffuse map. They are optional, so their absence is no warning.
        if (auto normal = resolver_.findCompanion(*diffuse, "_ddn"); normal && !roots_.refusal(*normal)) {
            m.normalTexture = normal->string();
            foundTextures_.insert(*normal);
        }
        if (auto specular = resolver_.findCompanion(*diffuse, "_spec"); specular && !roots_.refusal(*specular)) {
            m.specularTexture = specular->string();
            m.specularColor = glm::vec3(1.0f); // the map carries the strength
            foundTextures_.insert(*specular);
        }
    }

    // The absolute path when found, else the stored name's last component
    // (a placeholder is drawn for it; resolveTexture has warned).
    std::string resolvedOrName(const std::string& name, const std::string& role) {
        const std::optional<fs::path> found = resolveTexture(name, role);
        return found ? found->string() : std::string(textureFileName(name));
    }

    // Found: the absolute path. Missing: counted once per name, with a warning
    // that names the file and where it was looked for.
    std::optional<fs::path> resolveTexture(const std::string& name, const std::string& role) {
        std::string why;
        if (auto found = resolver_.find(name)) {
            const auto refused = roots_.refusal(*found); // a symbolic link out of the folders
            if (!refused) {
                foundTextures_.insert(*found);
                return found;
            }
            why = "was found as " + scene::capErrorText(found->string()) + ", which " + *refused;
        }
        if (missingTextures_.insert(asciiLower(name)).second) {
            if (why.empty()) {
                std::string folders;
                for (const fs::path& folder : resolver_.folders())
                    folders += (folders.empty() ? "" : ", ") + folder.string();
                why = "was not found in " + folders;
            }
            warn("texture '" + scene::capErrorText(name) + "' (" + role + ") " + why);
        }
        return std::nullopt;
    }

    static std::string materialName(const RawMaterial& raw, std::size_t index,
                                    std::set<std::string>& usedNames) {
        std::string name(textureFileName(raw.diffuseMap));
        if (const auto dot = name.rfind('.'); dot != std::string::npos && dot > 0)
            name.resize(dot);
        if (name.empty())
            name = "material " + std::to_string(index + 1);
        if (!usedNames.insert(name).second) {
            name += " #" + std::to_string(index + 1);
            usedNames.insert(name);
        }
        return name;
    }

    ByteReader r_;
    fs::path file_;
    TextureResolver resolver_;
    scene::ReadRoots roots_;
    ImportResult result_;
    std::vector<RawMaterial> materials_;
    std::vector<RawFrame> frames_;
    std::vector<int> parents_;
    std::size_t frameCount_ = 0;
    bool usesDefaultMaterial_ = false;
    std::set<fs::path> foundTextures_;
    std::set<std::string> missingTextures_;
};

std::string hexBytes(std::span<const std::uint8_t> bytes) {
    static constexpr char digits[] = "0123456789abcdef";
    std::string out;
    for (const std::uint8_t b : bytes) {
        if (!out.empty())
            out += ' ';
        out += digits[b >> 4];
        out += digits[b & 15];
    }
    return out;
}

// The signature is checked before parsing so that a short non-4ds file is
// "unknown format", not "truncated".
std::optional<scene::Error> checkSignature(std::span<const std::uint8_t> bytes, const fs::path& file) {
    const std::size_t n = std::min(bytes.size(), kMagic.size());
    if (!std::equal(bytes.begin(), bytes.begin() + std::ptrdiff_t(n), kMagic.begin()))
        return scene::Error{ErrorCode::UnknownFormat, file.string(), "byte offset 0",
                            "not a 4ds file: the signature is " + hexBytes(bytes.first(n)) +
                                ", expected 34 44 53 00 (\"4DS\\0\")"};
    if (n < kMagic.size())
        return scene::Error{ErrorCode::Truncated, file.string(), "byte offset 0",
                            "file ends after " + std::to_string(bytes.size()) +
                                " bytes, inside the 4-byte signature"};
    return std::nullopt;
}

} // namespace

bool looksLikeFourDs(std::span<const std::uint8_t> bytes) {
    if (bytes.size() < kMagic.size() + 2 || !std::equal(kMagic.begin(), kMagic.end(), bytes.begin()))
        return false;
    const std::uint16_t version = std::uint16_t(bytes[4] | (bytes[5] << 8));
    return version == kFourDsVersion;
}

scene::Expected<ImportResult> readFourDs(std::span<const std::uint8_t> bytes, const fs::path& file,
                                         const ImportOptions& options) {
    if (auto bad = checkSignature(bytes, file))
        return std::unexpected(std::move(*bad));
    // Exceptions stop here: FormatError carries the offset of the bad field;
    // anything else (out of memory) still becomes an error value.
    try {
        FourDsParser parser(bytes, file, options);
        ImportResult result = parser.parse();
        result.statedUnit = StatedUnit{1.0, "Mafia 4ds is in metres"};
        return result;
    } catch (const FormatError& e) {
        return scene::makeError(e.code(), file.string(), "byte offset " + std::to_string(e.offset()),
                                e.message());
    } catch (const std::bad_alloc&) {
        return scene::makeError(ErrorCode::OutOfRange, file.string(), "",
                                "out of memory while reading the model");
    } catch (const std::exception& e) {
        return scene::makeError(ErrorCode::InvalidValue, file.string(), "",
                                std::string("unexpected failure: ") + e.what());
    }
}

} // namespace lpv::importers
