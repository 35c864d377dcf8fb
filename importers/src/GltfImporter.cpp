#include "lpv/importers/GltfImporter.h"

#include "EmbeddedImages.h"
#include "TextEncoding.h"
#include "TextureResolver.h"
#include "lpv/importers/Importer.h"
#include "lpv/scene/FileRead.h"

#include <tiny_gltf.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <vector>

namespace lpv::importers {

using scene::ErrorCode;
using scene::makeError;

namespace {

// Images are decoded later through OpenImageIO: tinygltf only records the
// URI of external images; the bytes of embedded ones (data: URIs, .glb
// buffer views) are kept to be written to the embedded-image cache.
using EmbeddedBytes = std::map<int, std::vector<std::uint8_t>>;

bool keepUriOrEmbeddedBytes(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
                            const unsigned char* bytes, int size, void* embedded) {
    if (image->uri.empty() && bytes && size > 0)
        (*static_cast<EmbeddedBytes*>(embedded))[index].assign(bytes, bytes + size);
    return true;
}

// glTF URIs are percent-encoded ("my%20texture.png").
std::string percentDecode(const std::string& uri) {
    std::string out;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
            out += static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

struct Context {
    const tinygltf::Model& model;
    std::filesystem::path file;
    ImportResult& result;
    const EmbeddedBytes& embedded;
    const scene::ReadRoots& roots;
};

// The cache file of an embedded image, or "" (counted as missing, with a warning).
std::string embeddedImagePath(const Context& ctx, int source, const tinygltf::Image& image) {
    const auto bytes = ctx.embedded.find(source);
    if (bytes == ctx.embedded.end()) {
        ctx.result.warnings.push_back(ctx.file.string() + ": embedded image " + std::to_string(source) +
                                      " has no data (placeholder used)");
        ++ctx.result.stats.texturesMissing;
        return {};
    }
    auto stored = storeEmbeddedImage(bytes->second, image.mimeType);
    if (!stored) {
        ctx.result.warnings.push_back(ctx.file.string() + ": embedded image " + std::to_string(source) +
                                      " could not be stored: " + stored.error().describe() + " (placeholder used)");
        ++ctx.result.stats.texturesMissing;
        return {};
    }
    ++ctx.result.stats.texturesFound;
    return stored->string();
}

// Reads accessor `index` as `components` floats (or integer indices) per element, bounds checked.
scene::Expected<std::vector<float>> readFloats(const Context& ctx, int index, int components, const std::string& what) {
    const auto& m = ctx.model;
    const std::string where = what + " (accessor " + std::to_string(index) + ")";
    if (index < 0 || std::size_t(index) >= m.accessors.size())
        return makeError(ErrorCode::IndexOutOfRange, ctx.file.string(), where, "no such accessor");
    const tinygltf::Accessor& a = m.accessors[std::size_t(index)];
    if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || tinygltf::GetNumComponentsInType(std::uint32_t(a.type)) != components)
        return makeError(ErrorCode::TypeMismatch, ctx.file.string(), where,
                         "expected " + std::to_string(components) + " floats per element");
    if (a.bufferView < 0) {
        // All zeros by the specification (sparse accessors are not supported); the
        // cap keeps a lying count from allocating gigabytes.
        if (a.count > (std::size_t(1) << 26))
            return makeError(ErrorCode::OutOfRange, ctx.file.string(), where, "implausible element count");
        return std::vector<float>(a.count * std::size_t(components), 0.0f);
    }
    if (std::size_t(a.bufferView) >= m.bufferViews.size())
        return makeError(ErrorCode::IndexOutOfRange, ctx.file.string(), where, "buffer view out of range");
    const tinygltf::BufferView& v = m.bufferViews[std::size_t(a.bufferView)];
    if (v.buffer < 0 || std::size_t(v.buffer) >= m.buffers.size())
        return makeError(ErrorCode::IndexOutOfRange, ctx.file.string(), where, "buffer out of range");
    const auto& data = m.buffers[std::size_t(v.buffer)].data;
    const std::size_t elementSize = std::size_t(components) * sizeof(float);
    const std::size_t stride = v.byteStride ? v.byteStride : elementSize;
    const std::size_t start = v.byteOffset + a.byteOffset;
    if (a.count > 0 && (start + stride * (a.count - 1) + elementSize > data.size() ||
                        a.byteOffset + stride * (a.count - 1) + elementSize > v.byteLength))
        return makeError(ErrorCode::Truncated, ctx.file.string(), where, "accessor reads past the end of its buffer");
    std::vector<float> out(a.count * std::size_t(components));
    for (std::size_t i = 0; i < a.count; ++i)
        std::memcpy(&out[i * std::size_t(components)], data.data() + start + i * stride, elementSize);
    return out;
}

scene::Expected<std::vector<std::uint32_t>> readIndices(const Context& ctx, int index, std::size_t vertexCount) {
    const auto& m = ctx.model;
    const std::string where = "indices (accessor " + std::to_string(index) + ")";
    if (std::size_t(index) >= m.accessors.size())
        return makeError(ErrorCode::IndexOutOfRange, ctx.file.string(), where, "no such accessor");
    const tinygltf::Accessor& a = m.accessors[std::size_t(index)];
    const int size = tinygltf::GetComponentSizeInBytes(std::uint32_t(a.componentType));
    if (a.bufferView < 0 || std::size_t(a.bufferView) >= m.bufferViews.size() || (size != 1 && size != 2 && size != 4))
        return makeError(ErrorCode::InvalidValue, ctx.file.string(), where, "unsupported index accessor");
    const tinygltf::BufferView& v = m.bufferViews[std::size_t(a.bufferView)];
    if (v.buffer < 0 || std::size_t(v.buffer) >= m.buffers.size())
        return makeError(ErrorCode::IndexOutOfRange, ctx.file.string(), where, "buffer out of range");
    const auto& data = m.buffers[std::size_t(v.buffer)].data;
    const std::size_t stride = v.byteStride ? v.byteStride : std::size_t(size);
    const std::size_t start = v.byteOffset + a.byteOffset;
    if (a.count > 0 && start + stride * (a.count - 1) + std::size_t(size) > data.size())
        return makeError(ErrorCode::Truncated, ctx.file.string(), where, "indices read past the end of their buffer");
    std::vector<std::uint32_t> out(a.count);
    for (std::size_t i = 0; i < a.count; ++i) {
        std::uint32_t value = 0;
        std::memcpy(&value, data.data() + start + i * stride, std::size_t(size)); // little-endian hosts
        if (value >= vertexCount)
            return makeError(ErrorCode::IndexOutOfRange, ctx.file.string(), where,
                             "index " + std::to_string(i) + " is " + std::to_string(value) + ", but there are " +
                                 std::to_string(vertexCount) + " vertices");
        out[i] = value;
    }
    return out;
}

std::string texturePath(const Context& ctx, int textureIndex) {
    const auto& m = ctx.model;
    if (textureIndex < 0 || std::size_t(textureIndex) >= m.textures.size())
        return {};
    const int source = m.textures[std::size_t(textureIndex)].source;
    if (source < 0 || std::size_t(source) >= m.images.size()) {
        ctx.result.warnings.push_back(ctx.file.string() + ": texture " + std::to_string(textureIndex) +
                                      " has no image (placeholder used)");
        ++ctx.result.stats.texturesMissing;
        return {};
    }
    const tinygltf::Image& image = m.images[std::size_t(source)];
    if (image.uri.empty() || image.uri.starts_with("data:"))
        return embeddedImagePath(ctx, source, image);
    // Decoded first, so "%2e%2e/" is the "../" it means; then resolved
    // (links and "..") and checked against the folders the import may read.
    const std::string decoded = percentDecode(image.uri);
    const std::filesystem::path p = ctx.file.parent_path() / utf8Path(decoded);
    if (const auto why = ctx.roots.refusal(p)) {
        ctx.result.warnings.push_back(ctx.file.string() + ": texture '" + scene::capErrorText(decoded) + "' " +
                                      (*why == "no such file" ? std::string("not found") : *why) +
                                      " (placeholder used)");
        ++ctx.result.stats.texturesMissing;
        // The last component only: the stored uri would lead a later copy
        // into the project to the same place.
        return std::string(textureFileName(decoded));
    }
    ++ctx.result.stats.texturesFound;
    // Absolute, as importScene promises: a path relative to the working
    // directory would later be read as relative to the project file.
    return std::filesystem::absolute(p).lexically_normal().string();
}

glm::vec3 vec3Of(const std::vector<double>& v, glm::vec3 fallback) {
    return v.size() >= 3 ? glm::vec3(float(v[0]), float(v[1]), float(v[2])) : fallback;
}

scene::Material convertMaterial(const Context& ctx, const tinygltf::Material& in) {
    scene::Material out;
    out.name = in.name;
    out.shading = scene::ShadingModel::MetallicRoughness;
    const auto& pbr = in.pbrMetallicRoughness;
    out.diffuseColor = vec3Of(pbr.baseColorFactor, glm::vec3(1.0f));
    out.opacity = pbr.baseColorFactor.size() >= 4 ? float(pbr.baseColorFactor[3]) : 1.0f;
    out.metallic = float(pbr.metallicFactor);
    out.roughness = float(pbr.roughnessFactor);
    out.glossiness = 1.0f - out.roughness;
    out.diffuseTexture = texturePath(ctx, pbr.baseColorTexture.index);
    out.metallicRoughnessTexture = texturePath(ctx, pbr.metallicRoughnessTexture.index);
    out.normalTexture = texturePath(ctx, in.normalTexture.index);
    out.occlusionTexture = texturePath(ctx, in.occlusionTexture.index);
    out.emissiveTexture = texturePath(ctx, in.emissiveTexture.index);
    out.emissive = vec3Of(in.emissiveFactor, glm::vec3(0.0f));
    if (auto it = in.extensions.find("KHR_materials_emissive_strength"); it != in.extensions.end() &&
                                                                          it->second.Has("emissiveStrength"))
        out.emissive *= float(it->second.Get("emissiveStrength").GetNumberAsDouble());
    if (auto it = in.extensions.find("KHR_materials_transmission"); it != in.extensions.end()) {
        const tinygltf::Value& t = it->second;
        out.translucency = t.Has("transmissionFactor") ? float(t.Get("transmissionFactor").GetNumberAsDouble()) : 0.0f;
    }
    out.alphaMode = in.alphaMode == "MASK"    ? scene::AlphaMode::Mask
                    : in.alphaMode == "BLEND" ? scene::AlphaMode::Blend
                                              : scene::AlphaMode::Opaque;
    out.alphaCutoff = float(in.alphaCutoff);
    out.twoSided = in.doubleSided;
    // Out-of-range factors in a file are clamped rather than rejected: the scene stays usable.
    out.opacity = std::clamp(out.opacity, 0.0f, 1.0f);
    out.metallic = std::clamp(out.metallic, 0.0f, 1.0f);
    out.roughness = std::clamp(out.roughness, 0.0f, 1.0f);
    out.translucency = std::clamp(out.translucency, 0.0f, 1.0f);
    out.alphaCutoff = std::clamp(out.alphaCutoff, 0.0f, 1.0f);
    out.diffuseColor = glm::max(out.diffuseColor, glm::vec3(0.0f));
    out.emissive = glm::max(out.emissive, glm::vec3(0.0f));
    return out;
}

scene::Expected<scene::Mesh> convertMesh(const Context& ctx, const tinygltf::Mesh& in, std::uint32_t defaultMaterial) {
    scene::Mesh out;
    out.name = in.name;
    bool allHaveNormals = true, allHaveTangents = true, allHaveUvs = true;
    for (const tinygltf::Primitive& p : in.primitives)
        if (p.mode == TINYGLTF_MODE_TRIANGLES || p.mode == -1) {
            allHaveNormals &= p.attributes.count("NORMAL") > 0;
            allHaveTangents &= p.attributes.count("TANGENT") > 0;
            allHaveUvs &= p.attributes.count("TEXCOORD_0") > 0;
        }
    for (const tinygltf::Primitive& p : in.primitives) {
        if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != -1) {
            ctx.result.warnings.push_back(ctx.file.string() + ": mesh '" + in.name +
                                          "': a non-triangle primitive (mode " + std::to_string(p.mode) + ") was skipped");
            continue;
        }
        auto pos = p.attributes.find("POSITION");
        if (pos == p.attributes.end())
            return makeError(ErrorCode::MissingField, ctx.file.string(), "mesh '" + in.name + "'", "primitive without POSITION");
        auto positions = readFloats(ctx, pos->second, 3, "POSITION");
        if (!positions)
            return std::unexpected(positions.error());
        const std::size_t count = positions->size() / 3;
        const std::uint32_t base = std::uint32_t(out.positions.size());
        for (std::size_t i = 0; i < count; ++i)
            out.positions.emplace_back((*positions)[3 * i], (*positions)[3 * i + 1], (*positions)[3 * i + 2]);
        auto readInto = [&](const char* name, int comps, auto&& push) -> scene::Expected<void> {
            auto it = p.attributes.find(name);
            if (it == p.attributes.end())
                return {};
            auto values = readFloats(ctx, it->second, comps, name);
            if (!values)
                return std::unexpected(values.error());
            if (values->size() != count * std::size_t(comps))
                return makeError(ErrorCode::CorruptAsset, ctx.file.string(), name, "count differs from POSITION");
            for (std::size_t i = 0; i < count; ++i)
                push(&(*values)[i * std::size_t(comps)]);
            return {};
        };
        scene::Expected<void> ok;
        if (allHaveNormals && !(ok = readInto("NORMAL", 3, [&](const float* v) { out.normals.emplace_back(v[0], v[1], v[2]); })))
            return std::unexpected(ok.error());
        if (allHaveTangents &&
            !(ok = readInto("TANGENT", 4, [&](const float* v) { out.tangents.emplace_back(v[0], v[1], v[2], v[3]); })))
            return std::unexpected(ok.error());
        if (allHaveUvs && !(ok = readInto("TEXCOORD_0", 2, [&](const float* v) { out.uvs.emplace_back(v[0], 1.0f - v[1]); })))
            return std::unexpected(ok.error());
        scene::Submesh sub;
        sub.firstIndex = std::uint32_t(out.indices.size());
        sub.materialIndex = p.material >= 0 ? std::uint32_t(p.material) : defaultMaterial;
        if (p.indices >= 0) {
            auto indices = readIndices(ctx, p.indices, count);
            if (!indices)
                return std::unexpected(indices.error());
            for (std::uint32_t i : *indices)
                out.indices.push_back(base + i);
        } else {
            for (std::uint32_t i = 0; i < count; ++i)
                out.indices.push_back(base + i);
        }
        out.indices.resize(sub.firstIndex + (out.indices.size() - sub.firstIndex) / 3 * 3);
        sub.indexCount = std::uint32_t(out.indices.size()) - sub.firstIndex;
        out.submeshes.push_back(sub);
    }
    return out;
}

scene::Transform localTransform(const tinygltf::Node& n) {
    scene::Transform t;
    if (n.matrix.size() == 16) {
        glm::dmat4 m;
        std::memcpy(glm::value_ptr(m), n.matrix.data(), 16 * sizeof(double)); // column-major, like glTF
        const glm::mat4 f(m);
        t.translation = glm::vec3(f[3]);
        t.scale = {glm::length(glm::vec3(f[0])), glm::length(glm::vec3(f[1])), glm::length(glm::vec3(f[2]))};
        // A zero column (a collapsed node) has no direction to take a rotation from.
        if (t.scale.x > 0.0f && t.scale.y > 0.0f && t.scale.z > 0.0f) {
            const glm::mat3 r{glm::vec3(f[0]) / t.scale.x, glm::vec3(f[1]) / t.scale.y,
                              glm::vec3(f[2]) / t.scale.z};
            t.rotation = glm::quat_cast(r);
        }
        return t;
    }
    if (n.translation.size() == 3)
        t.translation = vec3Of(n.translation, glm::vec3(0.0f));
    if (n.rotation.size() == 4)
        t.rotation = glm::quat(float(n.rotation[3]), float(n.rotation[0]), float(n.rotation[1]), float(n.rotation[2]));
    if (n.scale.size() == 3)
        t.scale = vec3Of(n.scale, glm::vec3(1.0f));
    return t;
}

void addLightAndCamera(const Context& ctx, const tinygltf::Node& node, const glm::mat4& world) {
    const glm::vec3 position(world[3]);
    const glm::vec3 forward = glm::normalize(glm::vec3(world * glm::vec4(0, 0, -1, 0)));
    if (auto it = node.extensions.find("KHR_lights_punctual"); it != node.extensions.end() && it->second.Has("light")) {
        const int index = it->second.Get("light").GetNumberAsInt();
        if (index >= 0 && std::size_t(index) < ctx.model.lights.size()) {
            const tinygltf::Light& l = ctx.model.lights[std::size_t(index)];
            scene::Light light;
            light.name = l.name.empty() ? node.name : l.name;
            light.type = l.type == "directional" ? scene::LightType::Directional
                         : l.type == "spot"      ? scene::LightType::Spot
                                                 : scene::LightType::Point;
            light.color = vec3Of(l.color, glm::vec3(1.0f));
            // KHR_lights_punctual: lux for directional, candela (lm/sr) for point and spot.
            light.intensity = float(l.intensity);
            light.position = position;
            light.direction = forward;
            light.range = float(l.range);
            light.innerConeAngle = float(l.spot.innerConeAngle);
            light.outerConeAngle = float(l.spot.outerConeAngle);
            ctx.result.scene.lights.push_back(light);
        }
    }
    if (node.camera >= 0 && std::size_t(node.camera) < ctx.model.cameras.size()) {
        const tinygltf::Camera& c = ctx.model.cameras[std::size_t(node.camera)];
        if (c.type == "perspective") {
            scene::Camera cam;
            cam.name = c.name.empty() ? node.name : c.name;
            cam.position = position;
            cam.target = position + forward;
            cam.up = glm::normalize(glm::vec3(world * glm::vec4(0, 1, 0, 0)));
            cam.fovY = float(c.perspective.yfov);
            cam.nearPlane = float(c.perspective.znear);
            cam.farPlane = c.perspective.zfar > 0.0 ? float(c.perspective.zfar) : 1000.0f;
            ctx.result.scene.cameras.push_back(cam);
        }
    }
}

// glTF node graphs are trees by specification, but a file may list a child
// twice, share a node between parents (a 24-level graph of shared nodes
// expands to 2^24 copies) or close a cycle. Each node is imported once, under
// the first parent that reaches it, depth first without recursion (a
// 100,000-deep chain is fine); every other link to it is dropped with a
// warning that names both nodes.
void addNodeTrees(const Context& ctx, const std::vector<int>& roots) {
    const auto& nodes = ctx.model.nodes;
    struct Pending {
        int index;
        int from;   // the node that lists it, -1 for a scene root
        int parent; // its parent object, -1 for a root
        glm::mat4 parentWorld;
    };
    std::vector<bool> imported(nodes.size(), false);
    std::vector<Pending> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it)
        stack.push_back({*it, -1, -1, glm::mat4(1.0f)});
    std::size_t dropped = 0;
    auto describe = [&](int index) {
        std::string out = "node " + std::to_string(index);
        if (index >= 0 && std::size_t(index) < nodes.size() && !nodes[std::size_t(index)].name.empty())
            out += " ('" + scene::capErrorText(nodes[std::size_t(index)].name) + "')";
        return out;
    };
    auto dropLink = [&](const Pending& p, const std::string& why) {
        constexpr std::size_t kNamedLinks = 10;
        if (++dropped <= kNamedLinks)
            ctx.result.warnings.push_back(ctx.file.string() + ": " + (p.from < 0 ? "the scene" : describe(p.from)) +
                                          " lists " + describe(p.index) + ", " + why + "; that link is ignored");
    };
    while (!stack.empty()) {
        const Pending p = stack.back();
        stack.pop_back();
        if (p.index < 0 || std::size_t(p.index) >= nodes.size()) {
            dropLink(p, "which does not exist (there are " + std::to_string(nodes.size()) + " nodes)");
            continue;
        }
        if (imported[std::size_t(p.index)]) {
            dropLink(p, "which is already in the scene (a node listed twice, shared by two parents, or a cycle; "
                        "glTF nodes form trees)");
            continue;
        }
        imported[std::size_t(p.index)] = true;
        const tinygltf::Node& node = nodes[std::size_t(p.index)];
        scene::Object obj;
        obj.name = node.name;
        obj.parent = p.parent;
        obj.transform = localTransform(node);
        if (node.mesh >= 0 && std::size_t(node.mesh) < ctx.model.meshes.size())
            obj.mesh = node.mesh;
        const int self = int(ctx.result.scene.objects.size());
        ctx.result.scene.objects.push_back(obj);
        const glm::mat4 world = p.parentWorld * obj.transform.matrix();
        addLightAndCamera(ctx, node, world);
        for (auto child = node.children.rbegin(); child != node.children.rend(); ++child)
            stack.push_back({*child, p.index, self, world});
    }
    if (dropped > 10)
        ctx.result.warnings.push_back(ctx.file.string() + ": " + std::to_string(dropped - 10) +
                                      " more node links ignored for the same reasons");
}

// Every number of every node's transform as the 32-bit float we store: a
// glTF number such as 1e39 is finite as JSON but infinite as a float, and
// the error must name the input file and its field, not the project the
// import would write.
scene::Expected<void> checkNodeNumbers(const tinygltf::Model& model, const std::filesystem::path& file) {
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
        const tinygltf::Node& n = model.nodes[i];
        const std::pair<const char*, const std::vector<double>*> fields[] = {
            {"matrix", &n.matrix}, {"translation", &n.translation}, {"rotation", &n.rotation}, {"scale", &n.scale}};
        for (const auto& [name, values] : fields)
            for (std::size_t k = 0; k < values->size(); ++k)
                if (!std::isfinite(float((*values)[k])))
                    return makeError(ErrorCode::NonFinite, file.string(),
                                     "nodes[" + std::to_string(i) + "]." + name + "[" + std::to_string(k) + "]",
                                     std::to_string((*values)[k]) + " is not a finite 32-bit float");
    }
    return {};
}

// tinygltf's own file reader sizes a folder as a huge file (std::bad_alloc on
// an image uri of "."), and would block on a FIFO: ours reads regular files
// only, up to 2 GiB, and its "exists" says no to anything else, so such a
// uri takes the missing-file path (issue #29).
constexpr std::uintmax_t kMaxGltfFileBytes = std::uintmax_t{2} << 30;

bool gltfFileExists(const std::string& path, void*) { return !scene::notARegularFile(utf8Path(path)); }

// Reads only inside the import's folders (user data: the ReadRoots), so a
// buffer uri of "/etc/shadow" is an error that says why, and an image uri
// leading out is not read at all (texturePath warns about it).
bool gltfReadWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* roots) {
    const std::filesystem::path file = utf8Path(path);
    // tinygltf puts "File read error : <path> : " before what we say.
    auto fail = [&](const std::string& why) {
        if (err)
            *err += why + "\n";
        return false;
    };
    if (const auto why = static_cast<const scene::ReadRoots*>(roots)->refusal(file))
        return fail(*why);
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(file, ec);
    if (ec)
        return fail("cannot read its size: " + ec.message());
    if (size > kMaxGltfFileBytes)
        return fail("larger than 2 GiB");
    std::ifstream in(file, std::ios::binary);
    out->resize(std::size_t(size));
    if (size > 0 && !in.read(reinterpret_cast<char*>(out->data()), std::streamsize(size)))
        return fail("could not be read completely");
    return true;
}

// The size of a file tinygltf 2.9 asks before it reads one (its callback
// set has GetFileSizeInBytes), inside the same folders only.
bool gltfFileSize(std::size_t* size, std::string* err, const std::string& path, void* roots) {
    const std::filesystem::path file = utf8Path(path);
    if (const auto why = static_cast<const scene::ReadRoots*>(roots)->refusal(file)) {
        if (err)
            *err += *why + "\n";
        return false;
    }
    std::error_code ec;
    const std::uintmax_t bytes = std::filesystem::file_size(file, ec);
    if (ec) {
        if (err)
            *err += "cannot read its size: " + ec.message() + "\n";
        return false;
    }
    *size = std::size_t(bytes);
    return true;
}

// Our file callbacks for whichever tinygltf the build has (issue #49): 2.8
// (Debian 12) has four, 2.9 (Debian 13) adds GetFileSizeInBytes and refuses
// a set with any of them missing. Members are set by name, the new one
// where the struct has it, so one source builds against both.
template <typename Callbacks>
Callbacks gltfCallbacks(const scene::ReadRoots& roots) {
    Callbacks fs{};
    fs.FileExists = &gltfFileExists;
    fs.ExpandFilePath = &tinygltf::ExpandFilePath;
    fs.ReadWholeFile = &gltfReadWholeFile;
    fs.WriteWholeFile = &tinygltf::WriteWholeFile;
    if constexpr (requires { fs.GetFileSizeInBytes; })
        fs.GetFileSizeInBytes = &gltfFileSize;
    fs.user_data = const_cast<scene::ReadRoots*>(&roots);
    return fs;
}

// tinygltf's warnings about image files it could not find or read: each
// image gets our own warning in texturePath (with the reason and the
// placeholder), so these lines would only repeat it.
std::string withoutImageFileLines(const std::string& warn) {
    std::string out;
    std::size_t start = 0;
    while (start < warn.size()) {
        std::size_t end = warn.find('\n', start);
        if (end == std::string::npos)
            end = warn.size();
        const std::string_view line(warn.data() + start, end - start);
        const bool imageFile = line.starts_with("File not found") || line.starts_with("File read error") ||
                               line.starts_with("File is empty") || line.starts_with("Failed to load external 'uri' for image");
        if (!line.empty() && !imageFile)
            out += std::string(line) + "\n";
        start = end + 1;
    }
    if (!out.empty())
        out.pop_back();
    return out;
}

} // namespace

scene::Expected<ImportResult> importGltf(const std::filesystem::path& file, const ImportOptions& options) {
    const scene::ReadRoots roots = importReadRoots(file, options);
    tinygltf::TinyGLTF loader;
    EmbeddedBytes embedded;
    loader.SetImageLoader(keepUriOrEmbeddedBytes, &embedded);
    loader.SetFsCallbacks(gltfCallbacks<tinygltf::FsCallbacks>(roots));
    tinygltf::Model model;
    std::string err, warn;
    // Binary by content ("glTF" magic), whatever the extension says.
    char magic[4] = {};
    std::ifstream(file, std::ios::binary).read(magic, 4);
    const bool binary = std::string_view(magic, 4) == "glTF";
    // Absolute, so tinygltf's search for external files starts from the
    // scene's folder whatever the working directory (it also tries ".",
    // which the ReadRoots then refuse unless it is one of the folders).
    std::error_code ec;
    const std::string loadPath = std::filesystem::absolute(file, ec).string();
    const bool ok = binary ? loader.LoadBinaryFromFile(&model, &err, &warn, ec ? file.string() : loadPath)
                           : loader.LoadASCIIFromFile(&model, &err, &warn, ec ? file.string() : loadPath);
    if (!ok) {
        std::string why = err.empty() ? warn : err;
        while (!why.empty() && (why.back() == '\n' || why.back() == ' '))
            why.pop_back();
        return makeError(ErrorCode::CorruptAsset, file.string(), "", "glTF: " + why);
    }
    if (auto numbers = checkNodeNumbers(model, file); !numbers)
        return std::unexpected(numbers.error());
    ImportResult result;
    result.statedUnit = StatedUnit{1.0, "glTF is in metres by its spec"};
    result.cameraPlanesFromFile = true; // znear/zfar, in the file's metres
    if (const std::string own = withoutImageFileLines(warn); !own.empty())
        result.warnings.push_back(file.string() + ": " + own);
    Context ctx{model, file, result, embedded, roots};
    for (const tinygltf::Material& m : model.materials)
        result.scene.materials.push_back(convertMaterial(ctx, m));
    // Primitives without a material use the glTF default material.
    const std::uint32_t defaultMaterial = std::uint32_t(result.scene.materials.size());
    scene::Material fallback;
    fallback.name = "default";
    fallback.shading = scene::ShadingModel::MetallicRoughness;
    fallback.diffuseColor = glm::vec3(1.0f);
    result.scene.materials.push_back(fallback);
    for (const tinygltf::Mesh& m : model.meshes) {
        auto mesh = convertMesh(ctx, m, defaultMaterial);
        if (!mesh)
            return std::unexpected(mesh.error());
        result.scene.meshes.push_back(std::move(*mesh));
    }
    const int sceneIndex = model.defaultScene >= 0 ? model.defaultScene : 0;
    if (std::size_t(sceneIndex) < model.scenes.size())
        addNodeTrees(ctx, model.scenes[std::size_t(sceneIndex)].nodes);
    result.stats.objects = result.scene.objects.size();
    result.stats.triangles = result.scene.triangleCount();
    result.stats.materials = result.scene.materials.size();
    return result;
}

} // namespace lpv::importers
