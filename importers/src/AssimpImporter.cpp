// OBJ, 3DS and the other formats Assimp reads. Assimp only parses and
// triangulates here; welding, degenerate triangles, normals and tangents are
// left to cleanupMesh (importScene runs it for every format alike).
#include "lpv/importers/AssimpImporter.h"

#include "AssimpLog.h"
#include "TextEncoding.h"
#include "TextureResolver.h"

#include "lpv/scene/ProjectLimits.h"
#include "lpv/scene/SceneScale.h"

#include <assimp/DefaultIOSystem.h>
#include <assimp/Importer.hpp>
#include <assimp/MemoryIOWrapper.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string_view>

namespace lpv::importers {

using scene::ErrorCode;
using scene::makeError;

namespace {

glm::vec3 toVec3(const aiColor3D& c) { return {c.r, c.g, c.b}; }
glm::vec3 toVec3(const aiVector3D& v) { return {v.x, v.y, v.z}; }

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Resolves texture names case-insensitively and keeps the counts and
// warnings of one import (each missing name is reported once). A file found
// through a symbolic link that leads out of the import's folders is refused
// like any other reference outside them (importReadRoots).
class TextureSlots {
  public:
    TextureSlots(const std::filesystem::path& file, TextureResolver& resolver, const scene::ReadRoots& roots,
                 ImportResult& result)
        : file_(file), resolver_(resolver), roots_(roots), result_(result) {}

    // The absolute path, or the stored name's last component when the file is
    // missing or may not be read (the renderer draws a placeholder for it):
    // never the stored path itself, which a later copy into the project
    // would follow (an absolute `map_Kd /etc/shadow`).
    std::string resolve(const aiMaterial& m, aiTextureType type, const std::string& materialName) {
        aiString name;
        if (m.GetTextureCount(type) == 0 || m.GetTexture(type, 0, &name) != AI_SUCCESS || name.length == 0)
            return {};
        const std::string raw(name.C_Str());
        std::string why = "was not found";
        if (auto found = resolver_.find(raw)) {
            const auto refused = roots_.refusal(*found);
            if (!refused) {
                found_.insert(*found);
                return found->string();
            }
            why = "was found as " + scene::capErrorText(found->string()) + ", which " + *refused;
        }
        if (missing_.insert(asciiLower(textureFileName(raw))).second)
            result_.warnings.push_back(file_.string() + ": texture '" + scene::capErrorText(raw) + "' of material '" +
                                       materialName + "' " + why + "; a placeholder is drawn instead");
        return std::string(textureFileName(raw));
    }

    std::size_t foundCount() const { return found_.size(); }
    std::size_t missingCount() const { return missing_.size(); }

  private:
    const std::filesystem::path& file_;
    TextureResolver& resolver_;
    const scene::ReadRoots& roots_;
    ImportResult& result_;
    std::set<std::filesystem::path> found_;
    std::set<std::string> missing_;
};

void readColours(const aiMaterial& m, scene::Material& out) {
    aiColor3D c;
    if (m.Get(AI_MATKEY_COLOR_DIFFUSE, c) == AI_SUCCESS)
        out.diffuseColor = toVec3(c);
    if (m.Get(AI_MATKEY_COLOR_SPECULAR, c) == AI_SUCCESS)
        out.specularColor = toVec3(c);
    if (m.Get(AI_MATKEY_COLOR_EMISSIVE, c) == AI_SUCCESS)
        out.emissive = toVec3(c);
    float f = 0.0f;
    if (m.Get(AI_MATKEY_SHININESS, f) == AI_SUCCESS && std::isfinite(f))
        out.shininess = std::clamp(f, 1.0f, 4096.0f);
    if (m.Get(AI_MATKEY_OPACITY, f) == AI_SUCCESS && std::isfinite(f))
        out.opacity = std::clamp(f, 0.0f, 1.0f);
    // MTL's Tf (transmission filter): light passing through coloured glass.
    if (m.Get(AI_MATKEY_COLOR_TRANSPARENT, c) == AI_SUCCESS) {
        const float t = (c.r + c.g + c.b) / 3.0f;
        if (std::isfinite(t) && t < 1.0f - 1e-4f)
            out.translucency = std::clamp(1.0f - t, 0.0f, 1.0f);
    }
    int two = 0;
    if (m.Get(AI_MATKEY_TWOSIDED, two) == AI_SUCCESS)
        out.twoSided = two != 0;
}

scene::Material convertMaterial(const aiMaterial& m, const std::filesystem::path& file, TextureSlots& textures,
                                ImportResult& result) {
    scene::Material out;
    aiString name;
    if (m.Get(AI_MATKEY_NAME, name) == AI_SUCCESS)
        out.name = name.C_Str();
    readColours(m, out);
    if (out.opacity < 1.0f)
        out.alphaMode = scene::AlphaMode::Blend;
    // Normalised to [0, 1] over the usual Phong exponent range.
    out.glossiness = std::clamp(std::log2(out.shininess) / 12.0f, 0.0f, 1.0f);
    if (!finite(out.diffuseColor) || !finite(out.specularColor) || !finite(out.emissive)) {
        result.warnings.push_back(file.string() + ": material '" + out.name + "' has non-finite colours; reset");
        out.diffuseColor = glm::vec3(0.8f);
        out.specularColor = out.emissive = glm::vec3(0.0f);
    }
    out.diffuseColor = glm::max(out.diffuseColor, glm::vec3(0.0f));
    out.specularColor = glm::max(out.specularColor, glm::vec3(0.0f));
    out.emissive = glm::max(out.emissive, glm::vec3(0.0f));
    out.diffuseTexture = textures.resolve(m, aiTextureType_DIFFUSE, out.name);
    out.normalTexture = textures.resolve(m, aiTextureType_NORMALS, out.name);
    // OBJ's map_bump and 3DS bump maps arrive as HEIGHT: turned into normals by the renderer.
    out.heightTexture = textures.resolve(m, aiTextureType_HEIGHT, out.name);
    out.specularTexture = textures.resolve(m, aiTextureType_SPECULAR, out.name);
    out.emissiveTexture = textures.resolve(m, aiTextureType_EMISSIVE, out.name);
    out.alphaTexture = textures.resolve(m, aiTextureType_OPACITY, out.name);
    if (!out.alphaTexture.empty() && out.alphaMode == scene::AlphaMode::Opaque)
        out.alphaMode = scene::AlphaMode::Mask;
    return out;
}

// Assimp's vertices as they are (one per face corner for OBJ); cleanupMesh
// welds them and drops degenerate triangles afterwards.
scene::Mesh convertMesh(const aiMesh& in) {
    scene::Mesh out;
    out.name = in.mName.C_Str();
    out.positions.reserve(in.mNumVertices);
    for (unsigned i = 0; i < in.mNumVertices; ++i)
        out.positions.push_back(toVec3(in.mVertices[i]));
    if (in.HasNormals())
        for (unsigned i = 0; i < in.mNumVertices; ++i)
            out.normals.push_back(toVec3(in.mNormals[i]));
    if (in.HasTextureCoords(0))
        for (unsigned i = 0; i < in.mNumVertices; ++i)
            out.uvs.emplace_back(in.mTextureCoords[0][i].x, in.mTextureCoords[0][i].y);
    out.indices.reserve(std::size_t(in.mNumFaces) * 3);
    for (unsigned f = 0; f < in.mNumFaces; ++f) {
        const aiFace& face = in.mFaces[f];
        if (face.mNumIndices == 3) // points and lines are removed by SortByPType
            out.indices.insert(out.indices.end(), {face.mIndices[0], face.mIndices[1], face.mIndices[2]});
    }
    if (!out.indices.empty())
        out.submeshes.push_back({0, std::uint32_t(out.indices.size()), in.mMaterialIndex});
    return out;
}

scene::Transform toTransform(const aiMatrix4x4& m) {
    aiVector3D s, p;
    aiQuaternion q;
    m.Decompose(s, q, p);
    scene::Transform t;
    t.translation = toVec3(p);
    t.rotation = glm::normalize(glm::quat(q.w, q.x, q.y, q.z));
    t.scale = toVec3(s);
    return t;
}

glm::mat4 toGlm(const aiMatrix4x4& m) { return glm::transpose(glm::make_mat4(&m.a1)); }

// Assimp nodes become objects; a node with several meshes gets one child
// object per mesh, since an object references at most one mesh. Meshes
// without triangles (an OBJ object with vertices and no faces) are skipped.
class NodeConverter {
  public:
    NodeConverter(const std::vector<int>& meshIndex, scene::Scene& out) : meshIndex_(meshIndex), out_(out) {}

    void add(const aiNode& node, int parent, const glm::mat4& parentWorld) {
        scene::Object obj;
        obj.name = node.mName.C_Str();
        obj.parent = parent;
        obj.transform = toTransform(node.mTransformation);
        const glm::mat4 world = parentWorld * toGlm(node.mTransformation);
        worldOf_[obj.name] = world;
        localTranslationOf_[obj.name] = obj.transform.translation;
        const int self = int(out_.objects.size());
        out_.objects.push_back(obj);
        std::vector<int> meshes;
        for (unsigned i = 0; i < node.mNumMeshes; ++i)
            if (node.mMeshes[i] < meshIndex_.size() && meshIndex_[node.mMeshes[i]] >= 0)
                meshes.push_back(meshIndex_[node.mMeshes[i]]);
        if (meshes.size() == 1)
            out_.objects[std::size_t(self)].mesh = meshes[0];
        else
            for (std::size_t i = 0; i < meshes.size(); ++i) {
                scene::Object part;
                part.name = out_.meshes[std::size_t(meshes[i])].name;
                if (part.name.empty())
                    part.name = obj.name + " #" + std::to_string(i + 1);
                part.parent = self;
                part.mesh = meshes[i];
                out_.objects.push_back(part);
            }
        for (unsigned c = 0; c < node.mNumChildren; ++c)
            add(*node.mChildren[c], self, world);
    }

    // Lights and cameras are placed by the node of the same name.
    glm::mat4 worldOf(const aiString& name) const {
        const auto it = worldOf_.find(name.C_Str());
        return it == worldOf_.end() ? glm::mat4(1.0f) : it->second;
    }

    // A camera's or light's position relative to its node. Assimp documents
    // it as relative, but its 3DS reader also puts the same position into the
    // node's translation; counting it twice would move the camera away.
    glm::vec3 localPosition(const aiString& name, const aiVector3D& position) const {
        const auto it = localTranslationOf_.find(name.C_Str());
        const glm::vec3 p = toVec3(position);
        if (it != localTranslationOf_.end() && glm::length(p) > 0.0f &&
            glm::length(it->second - p) <= 1e-5f * glm::length(p))
            return glm::vec3(0.0f);
        return p;
    }

  private:
    const std::vector<int>& meshIndex_;
    scene::Scene& out_;
    std::map<std::string, glm::mat4> worldOf_;
    std::map<std::string, glm::vec3> localTranslationOf_;
};

// Our point lights fall off with the squared distance. A point light outside
// the scene's bounds is meant as the sun (3ds Max omni lights have no falloff
// by default, and 3DS stores none: Assimp reports its default attenuation), as
// Sponza's "Sun01" 60 units above the atrium: it becomes a directional light
// shining from where it is towards the scene's centre.
void sunFromDistantOmni(scene::Light& light, const scene::Bounds& bounds, const std::filesystem::path& file,
                        ImportResult& result) {
    if (light.type != scene::LightType::Point || bounds.empty())
        return;
    const glm::vec3 p = light.position;
    const bool outside = glm::any(glm::lessThan(p, bounds.min)) || glm::any(glm::greaterThan(p, bounds.max));
    const glm::vec3 towardsScene = bounds.center() - p;
    if (!outside || glm::length(towardsScene) <= 0.0f)
        return;
    light.type = scene::LightType::Directional;
    light.direction = glm::normalize(towardsScene);
    result.warnings.push_back(file.string() + ": light '" + light.name +
                              "' is a point light outside the scene; imported as a "
                              "directional light (a sun) shining towards the scene's centre");
}

scene::Light convertLight(const aiLight& l, const glm::mat4& world, const glm::vec3& localPosition) {
    scene::Light light;
    light.name = l.mName.C_Str();
    light.type = l.mType == aiLightSource_DIRECTIONAL ? scene::LightType::Directional
                 : l.mType == aiLightSource_SPOT      ? scene::LightType::Spot
                                                      : scene::LightType::Point;
    const glm::vec3 colour = toVec3(l.mColorDiffuse);
    const float peak = std::max({colour.r, colour.g, colour.b});
    light.intensity = peak > 0.0f && std::isfinite(peak) ? peak : 1.0f;
    light.color = peak > 0.0f && std::isfinite(peak) ? colour / peak : glm::vec3(1.0f);
    light.position = glm::vec3(world * glm::vec4(localPosition, 1.0f));
    const glm::vec3 direction = glm::mat3(world) * toVec3(l.mDirection);
    if (glm::length(direction) > 0.0f && finite(direction))
        light.direction = glm::normalize(direction);
    if (light.type == scene::LightType::Spot) {
        light.outerConeAngle = std::clamp(l.mAngleOuterCone, 0.0f, 1.5707f);
        light.innerConeAngle = std::clamp(l.mAngleInnerCone, 0.0f, light.outerConeAngle);
    }
    return light;
}

scene::Camera convertCamera(const aiCamera& c, const glm::mat4& world, const glm::vec3& localPosition) {
    scene::Camera cam;
    cam.name = c.mName.C_Str();
    cam.position = glm::vec3(world * glm::vec4(localPosition, 1.0f));
    const glm::vec3 look = glm::mat3(world) * toVec3(c.mLookAt);
    cam.target = cam.position + (glm::length(look) > 0.0f ? glm::normalize(look) : glm::vec3(0, 0, -1));
    // Some readers leave mUp at its default in the file's own axes (3DS is Z up,
    // so (0, 1, 0) ends up horizontal): an up more than 60 degrees from +Y is
    // not believed, and +Y, our up, is used instead.
    const glm::vec3 up = glm::mat3(world) * toVec3(c.mUp);
    const bool believable = glm::length(up) > 0.0f && finite(up) && glm::normalize(up).y > 0.5f;
    cam.up = believable ? glm::normalize(up) : glm::vec3(0, 1, 0);
    // A camera looking straight up or down (3DS/CameraRollAnim.3ds: Z-up
    // "forward" becomes +Y) would get +Y, parallel to its view: a NaN view
    // matrix, and Embree aborted on its rays. Then the file's own up, which
    // 3DS keeps perpendicular, is the better guess.
    const glm::vec3 view = glm::normalize(cam.target - cam.position);
    if (glm::length(glm::cross(view, cam.up)) < 1e-3f && glm::length(up) > 0.0f && finite(up) &&
        glm::length(glm::cross(view, glm::normalize(up))) >= 1e-3f)
        cam.up = glm::normalize(up);
    // Assimp's mHorizontalFOV is the half angle, centre line to the left border.
    const float aspect = c.mAspect > 0.0f ? c.mAspect : 16.0f / 9.0f;
    const float fovY = 2.0f * std::atan(std::tan(c.mHorizontalFOV) / aspect);
    if (std::isfinite(fovY) && fovY > 0.0f && fovY < 3.1f)
        cam.fovY = fovY;
    return cam;
}

// ---- material libraries ----------------------------------------------------

// Assimp 5.2.5 (Debian 12's) reads an MTL statement into "the current
// material" without checking that there is one for texture statements
// (map_Kd, bump, disp, norm, refl, ...) and `a` (anisotropy): before the
// first `newmtl` there is none (when the OBJ names its library before any
// `usemtl`), and it crashes (fuzz_obj). It also throws "File is too small" on
// a library of 1 to 7 bytes, failing the import and leaking the stream it
// opened. So a material library is read here and served from memory with
// every statement line before its first `newmtl` dropped (blank and comment
// lines stay, and every line keeps its end, so line numbers hold), padded
// with line ends to 8 bytes when shorter.
//
// Lines as Assimp's MTL parser sees them: they end at '\n', '\r', '\f' or
// '\0'; spaces and tabs in front are skipped, except on the file's first line,
// which Assimp then skips whole, so the first `newmtl` is served without them.
constexpr std::uintmax_t kMaxMaterialLibraryBytes = 64u << 20;

bool isAssimpLineEnd(char c) { return c == '\n' || c == '\r' || c == '\f' || c == '\0'; }

struct RepairedLibrary {
    std::string text;
    std::size_t droppedLines = 0;
};

RepairedLibrary repairMaterialLibrary(std::string_view in) {
    if (in.starts_with("\xEF\xBB\xBF")) // a UTF-8 byte order mark: Assimp drops it too
        in.remove_prefix(3);
    RepairedLibrary out;
    out.text.reserve(in.size() + 8);
    std::size_t begin = 0;
    while (begin < in.size()) {
        std::size_t end = begin;
        while (end < in.size() && !isAssimpLineEnd(in[end]))
            ++end;
        const std::string_view line = in.substr(begin, end - begin);
        const std::size_t first = line.find_first_not_of(" \t");
        const std::string_view body = first == std::string_view::npos ? std::string_view() : line.substr(first);
        if (body.starts_with("newmtl") && (body.size() == 6 || body[6] == ' ' || body[6] == '\t')) {
            out.text += body;
            out.text += in.substr(end); // from here on every statement has a material
            break;
        }
        if (body.empty() || body.front() == '#')
            out.text += line;
        else
            ++out.droppedLines;
        if (end < in.size())
            out.text += in[end];
        begin = end + 1;
    }
    if (!out.text.empty() && out.text.size() < 8)
        out.text.append(8 - out.text.size(), '\n');
    return out;
}

// The `newmtl` statements of a (repaired) library, counted as Assimp's
// parser sees lines, so an import of more materials than a project holds is
// refused before Assimp builds them (1,000,000 of them cost it 5.4 GiB).
std::size_t countMaterialStatements(std::string_view text) {
    std::size_t count = 0;
    std::size_t begin = 0;
    while (begin < text.size()) {
        std::size_t end = begin;
        while (end < text.size() && !isAssimpLineEnd(text[end]))
            ++end;
        std::string_view line = text.substr(begin, end - begin);
        const std::size_t first = line.find_first_not_of(" \t");
        line = first == std::string_view::npos ? std::string_view() : line.substr(first);
        if (line.starts_with("newmtl") && (line.size() == 6 || line[6] == ' ' || line[6] == '\t'))
            ++count;
        begin = end + 1;
    }
    return count;
}

bool hasExtension(const std::string& file, std::string_view extension) {
    if (file.size() < extension.size())
        return false;
    return std::equal(extension.begin(), extension.end(), file.end() - std::ptrdiff_t(extension.size()),
                      [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == b; });
}

// A stream of the model file itself that tells the IO system while it is open.
class CountedStream : public Assimp::IOStream {
  public:
    CountedStream(Assimp::IOStream* inner, std::shared_ptr<int> open) : inner_(inner), open_(std::move(open)) {
        ++*open_;
    }
    ~CountedStream() override {
        delete inner_;
        --*open_;
    }
    CountedStream(const CountedStream&) = delete;
    CountedStream& operator=(const CountedStream&) = delete;

    size_t Read(void* buffer, size_t size, size_t count) override { return inner_->Read(buffer, size, count); }
    size_t Write(const void* buffer, size_t size, size_t count) override { return inner_->Write(buffer, size, count); }
    aiReturn Seek(size_t offset, aiOrigin origin) override { return inner_->Seek(offset, origin); }
    size_t Tell() const override { return inner_->Tell(); }
    size_t FileSize() const override { return inner_->FileSize(); }
    void Flush() override { inner_->Flush(); }

  private:
    Assimp::IOStream* inner_;
    std::shared_ptr<int> open_;
};

// Assimp opens the files a model names itself (an OBJ's `mtllib`, a glTF's
// buffers through Assimp): only regular files inside the import's folders
// (ReadRoots), so `mtllib /etc/shadow` is a missing material library with
// Assimp's own warning, not a read of the system file. A FIFO is refused
// rather than blocked on.
//
// Material libraries are repaired (above): files named *.mtl, and in an OBJ
// import every file opened while the OBJ itself is open (Assimp's OBJ parser
// holds it open while it parses, and opens nothing else but the libraries its
// `mtllib` lines name, whatever their name, the OBJ included). What was
// repaired is noted for the import's warnings.
class RootedIOSystem : public Assimp::DefaultIOSystem {
  public:
    RootedIOSystem(scene::ReadRoots roots, std::string model)
        : roots_(std::move(roots)), model_(std::move(model)), objModel_(hasExtension(model_, ".obj")) {}

    bool Exists(const char* file) const override { return file && !roots_.refusal(utf8Path(file)); }

    Assimp::IOStream* Open(const char* file, const char* mode) override {
        const bool reading = mode && mode[0] == 'r';
        if (!file || !reading || roots_.refusal(utf8Path(file)))
            return nullptr;
        const std::string name(file);
        if (hasExtension(name, ".mtl") || (objModel_ && *modelOpen_ > 0))
            return openMaterialLibrary(name, mode);
        Assimp::IOStream* stream = Assimp::DefaultIOSystem::Open(file, mode);
        if (stream && objModel_ && name == model_)
            return new CountedStream(stream, modelOpen_);
        return stream;
    }

    const std::vector<std::string>& notes() const { return notes_; }
    // Why the import must fail (too many materials); empty when it need not.
    const std::string& refusal() const { return refusal_; }

  private:
    Assimp::IOStream* openMaterialLibrary(const std::string& name, const char* mode) {
        const std::unique_ptr<Assimp::IOStream> file(Assimp::DefaultIOSystem::Open(name.c_str(), mode));
        if (!file)
            return nullptr;
        const std::size_t size = file->FileSize();
        if (size > kMaxMaterialLibraryBytes) {
            notes_.push_back("material library '" + scene::capErrorText(name) + "' is " + std::to_string(size) +
                             " bytes, more than 64 MiB; not read");
            return nullptr;
        }
        std::string bytes(size, '\0');
        bytes.resize(size ? file->Read(bytes.data(), 1, size) : 0);
        const RepairedLibrary repaired = repairMaterialLibrary(bytes);
        if (countedLibraries_.insert(name).second)
            materials_ += countMaterialStatements(repaired.text);
        if (materials_ > scene::kMaxMaterials) {
            refusal_ = "material library '" + scene::capErrorText(name) + "' brings the materials to " +
                       std::to_string(materials_) + ", more than a project can hold (" +
                       std::to_string(scene::kMaxMaterials) + "); refused before parsing it";
            // Ends Assimp's parse here (ReadFile catches it and returns no
            // scene): left to go on, it would make a material for every
            // `usemtl` of the model, each looked up by a linear search.
            throw std::runtime_error(refusal_);
        }
        if (repaired.droppedLines > 0)
            notes_.push_back("material library '" + scene::capErrorText(name) + "': " +
                             std::to_string(repaired.droppedLines) +
                             (repaired.droppedLines == 1 ? " line" : " lines") +
                             " before its first 'newmtl' dropped (statements outside any material)");
        auto* buffer = new std::uint8_t[std::max<std::size_t>(repaired.text.size(), 1)];
        std::copy(repaired.text.begin(), repaired.text.end(), buffer);
        return new Assimp::MemoryIOStream(buffer, repaired.text.size(), true); // frees it with delete[]
    }

    scene::ReadRoots roots_;
    std::string model_; // the path as given to ReadFile, which Assimp opens it by
    bool objModel_;
    std::shared_ptr<int> modelOpen_ = std::make_shared<int>(0);
    std::vector<std::string> notes_;
    // `newmtl` statements in the libraries opened so far, and the default
    // material Assimp's OBJ reader always adds.
    std::size_t materials_ = 1;
    std::set<std::string> countedLibraries_;
    std::string refusal_;
};

// ---- units ---------------------------------------------------------------

std::string numberText(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", v);
    return text;
}

// A metadata number of any of the types Assimp stores numbers as.
std::optional<double> metadataNumber(const aiScene& in, const char* key) {
    if (!in.mMetaData)
        return std::nullopt;
    const aiMetadata& md = *in.mMetaData;
    for (unsigned i = 0; i < md.mNumProperties; ++i) {
        if (std::string_view(md.mKeys[i].C_Str()) != key || !md.mValues[i].mData)
            continue;
        const void* data = md.mValues[i].mData;
        switch (md.mValues[i].mType) {
        case AI_DOUBLE:
            return *static_cast<const double*>(data);
        case AI_FLOAT:
            return double(*static_cast<const float*>(data));
        case AI_INT32:
            return double(*static_cast<const std::int32_t*>(data));
        case AI_UINT64:
            return double(*static_cast<const std::uint64_t*>(data));
        default:
            return std::nullopt;
        }
    }
    return std::nullopt;
}

// FBX's GlobalSettings UnitScaleFactor: centimetres per unit of the file
// (1 for centimetres, 100 for metres). Assimp 5.2 reports it as metadata
// and leaves the vertices in the file's unit (we do not ask it to scale).
std::optional<StatedUnit> fbxUnit(const aiScene& in) {
    const std::optional<double> cm = metadataNumber(in, "UnitScaleFactor");
    if (!cm || !std::isfinite(*cm) || *cm <= 0.0)
        return std::nullopt;
    static constexpr std::pair<double, const char*> kNames[] = {
        {0.1, "millimetres"}, {1.0, "centimetres"}, {2.54, "inches"},   {30.48, "feet"},
        {91.44, "yards"},     {100.0, "metres"},    {1e5, "kilometres"}};
    std::string name = numberText(*cm) + " cm per unit";
    for (const auto& [value, unit] : kNames)
        if (std::abs(*cm - value) <= 1e-6 * value)
            name = unit;
    return StatedUnit{*cm * 0.01, "the file's UnitScaleFactor " + numberText(*cm) + ": " + name};
}

// Collada's <unit meter="..."/> in its <asset>, at the top of the file. Assimp
// applies it to the root node itself; nothing when the file names none.
std::optional<double> colladaUnitMetres(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::string head(std::size_t(256) << 10, '\0');
    in.read(head.data(), std::streamsize(head.size()));
    head.resize(std::size_t(in.gcount()));
    const std::size_t unit = head.find("<unit");
    if (unit == std::string::npos)
        return std::nullopt;
    const std::size_t end = head.find('>', unit);
    const std::string tag = head.substr(unit, end == std::string::npos ? std::string::npos : end - unit);
    const std::size_t meter = tag.find("meter=");
    if (meter == std::string::npos || meter + 7 >= tag.size())
        return std::nullopt;
    const char* begin = tag.c_str() + meter + 7; // past the quote
    char* stop = nullptr;
    const double metres = std::strtod(begin, &stop);
    if (stop == begin || !std::isfinite(metres) || metres <= 0.0)
        return std::nullopt;
    return metres;
}

} // namespace

bool assimpReads(const std::filesystem::path& file) {
    Assimp::Importer importer;
    return importer.IsExtensionSupported(file.extension().string());
}

scene::Expected<ImportResult> importWithAssimp(const std::filesystem::path& file, const ImportOptions& options) {
    Assimp::Importer importer;
    auto* io = new RootedIOSystem(importReadRoots(file, options), file.string());
    importer.SetIOHandler(io); // the importer owns it
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_LINE | aiPrimitiveType_POINT);
    AssimpLogCapture log; // Assimp's own warnings ("failed to locate material ...") become ours
    const aiScene* in = importer.ReadFile(
        file.string(), aiProcess_Triangulate | aiProcess_SortByPType | aiProcess_ValidateDataStructure);
    if (!io->refusal().empty())
        return makeError(ErrorCode::OutOfRange, file.string(), "materials", io->refusal());
    if (!in || !in->mRootNode)
        return makeError(ErrorCode::UnknownFormat, file.string(), "",
                         std::string("Assimp could not read it: ") + importer.GetErrorString());
    if (auto fits = scene::checkMaterialCount(in->mNumMaterials, file.string(), "materials"); !fits)
        return std::unexpected(fits.error());
    ImportResult result;
    for (const std::string& note : io->notes())
        result.warnings.push_back(file.string() + ": " + note);
    for (const std::string& message : log.messages())
        result.warnings.push_back(file.string() + ": " + message);

    TextureResolver resolver(textureFoldersFor(file, options.textureSearchPaths));
    const scene::ReadRoots roots = importReadRoots(file, options);
    TextureSlots textures(file, resolver, roots, result);
    for (unsigned i = 0; i < in->mNumMaterials; ++i)
        result.scene.materials.push_back(convertMaterial(*in->mMaterials[i], file, textures, result));
    if (result.scene.materials.empty()) {
        scene::Material fallback;
        fallback.name = "default";
        result.scene.materials.push_back(fallback);
    }

    std::vector<int> meshIndex(in->mNumMeshes, -1);
    for (unsigned i = 0; i < in->mNumMeshes; ++i) {
        scene::Mesh mesh = convertMesh(*in->mMeshes[i]);
        if (mesh.indices.empty()) {
            result.warnings.push_back(file.string() + ": mesh '" + mesh.name + "' has " +
                                      std::to_string(mesh.positions.size()) + " vertices but no faces; skipped");
            continue;
        }
        for (scene::Submesh& s : mesh.submeshes)
            s.materialIndex = std::min<std::uint32_t>(s.materialIndex, std::uint32_t(result.scene.materials.size() - 1));
        meshIndex[i] = int(result.scene.meshes.size());
        result.scene.meshes.push_back(std::move(mesh));
    }
    NodeConverter nodes(meshIndex, result.scene);
    nodes.add(*in->mRootNode, -1, glm::mat4(1.0f));
    const scene::Bounds bounds = result.scene.worldBounds();
    for (unsigned i = 0; i < in->mNumLights; ++i) {
        const aiLight& l = *in->mLights[i];
        scene::Light light = convertLight(l, nodes.worldOf(l.mName), nodes.localPosition(l.mName, l.mPosition));
        sunFromDistantOmni(light, bounds, file, result);
        result.scene.lights.push_back(light);
    }
    for (unsigned i = 0; i < in->mNumCameras; ++i) {
        const aiCamera& c = *in->mCameras[i];
        result.scene.cameras.push_back(
            convertCamera(c, nodes.worldOf(c.mName), nodes.localPosition(c.mName, c.mPosition)));
    }

    result.stats.texturesFound = textures.foundCount();
    result.stats.texturesMissing = textures.missingCount();
    if (auto unit = fbxUnit(*in)) {
        result.statedUnit = std::move(*unit);
    } else if (hasExtension(file.string(), ".dae")) {
        const std::optional<double> metres = colladaUnitMetres(file);
        const std::string how = metres ? "the file's Collada <unit meter=\"" + numberText(*metres) + "\">"
                                       : "Collada is in metres when it names no <unit>";
        if (options.metresPerUnit && metres && *metres != 1.0) {
            // The user's unit replaces the file's, which Assimp already applied.
            scene::scaleSceneLengths(result.scene, 1.0 / *metres, {.cameraPlanes = false});
            result.statedUnit = StatedUnit{*metres, how};
        } else {
            result.statedUnit = StatedUnit{1.0, how};
        }
    }
    return result;
}

} // namespace lpv::importers
