// The scene field tables (SceneFields.h) and what they drive: the project
// file's bytes, the hashes, the fuzz dictionary and the format docs.
#include "FieldChanges.h"
#include "ProjectTestSupport.h"

#include "lpv/scene/SceneFields.h"

#include "TestPaths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

using namespace lpv;

namespace {

std::vector<unsigned char> bytesOf(const auto& s) {
    std::vector<unsigned char> out;
    scene::hashFields(s, [&](const void* p, std::size_t n) {
        const auto* c = static_cast<const unsigned char*>(p);
        out.insert(out.end(), c, c + n);
    });
    return out;
}

template <class S> std::vector<std::string> fieldsOutsideTheHash() {
    return test::fieldsNotAffecting(S{}, [](const S& a, const S& b) { return bytesOf(a) != bytesOf(b); });
}

class SceneFieldsTest : public test::TempDirTest {
  protected:
    SceneFieldsTest() : TempDirTest("scene-fields-") {}
};

} // namespace

// The tables list fields in the order files have always had them: the
// Cornell box loads and saves to the very bytes it was committed with.
TEST_F(SceneFieldsTest, CornellBoxSavesToTheSameBytes) {
    const std::filesystem::path source =
        std::filesystem::path(test::kSourceDir) / "projects/cornell-box/cornell-box.lpvproj";
    const auto project = scene::loadProject(source);
    ASSERT_TRUE(project.has_value()) << project.error().describe();
    const std::filesystem::path copy = dir_ / "cornell-box.lpvproj";
    const auto saved = scene::saveProject(*project, copy);
    ASSERT_TRUE(saved.has_value()) << saved.error().describe();
    EXPECT_EQ(test::readFile(copy), test::readFile(source));
}

// The reuse hash and the radiosity signature hash through hashFields: every
// field changes it but the names, which change no output.
TEST(SceneFields, EveryFieldButNamesAndListsIsHashed) {
    EXPECT_EQ(fieldsOutsideTheHash<scene::Light>(), std::vector<std::string>{"name"});
    EXPECT_EQ(fieldsOutsideTheHash<scene::Material>(), std::vector<std::string>{"name"});
    EXPECT_EQ(fieldsOutsideTheHash<scene::Camera>(), std::vector<std::string>{"name"});
    EXPECT_EQ(fieldsOutsideTheHash<scene::Sky>(), std::vector<std::string>{});
    EXPECT_EQ(fieldsOutsideTheHash<scene::Object>(), (std::vector<std::string>{"name", "lods"}));
}

// What the editor offers (editRange) is inside what the loader takes.
template <class S> void expectEditRangesInsideRanges() {
    scene::forEachField<S>([](const auto& field) {
        const scene::FieldRange edit = field.editRange;
        if (!edit.bounded())
            return;
        EXPECT_TRUE(std::isfinite(edit.min) && std::isfinite(edit.max))
            << field.name << ": a spin box needs finite ends";
        if (!edit.openMin)
            EXPECT_TRUE(field.range.contains(float(edit.min))) << field.name << " " << edit.describe();
        if (!edit.openMax)
            EXPECT_TRUE(field.range.contains(float(edit.max))) << field.name << " " << edit.describe();
    });
}

TEST(SceneFields, EditorRangesLieInsideTheLoadersRanges) {
    expectEditRangesInsideRanges<scene::Light>();
    expectEditRangesInsideRanges<scene::Material>();
    expectEditRangesInsideRanges<scene::Object>();
    expectEditRangesInsideRanges<scene::Camera>();
    expectEditRangesInsideRanges<scene::Sky>();
}

// The loader's message for the spot cone the editor used to allow.
TEST(SceneFields, RangesDescribeTheirOpenEnds) {
    EXPECT_EQ(scene::fieldOf<&scene::Light::outerConeAngle>().range.describe(), "(0, 1.5707963267948966]");
    EXPECT_EQ(scene::fieldOf<&scene::Light::innerConeAngle>().range.describe(), "[0, 1.5707963267948966]");
    EXPECT_EQ(scene::fieldOf<&scene::Light::radius>().range.describe(), "> 0");
    EXPECT_EQ(scene::fieldOf<&scene::Sky::intensity>().range.describe(), ">= 0");
    EXPECT_FALSE(scene::fieldOf<&scene::Light::outerConeAngle>().range.contains(0.0f));
}

// fuzz_project's dictionary names every field a project file has.
TEST(SceneFields, FuzzDictionaryHoldsEveryFieldName) {
    const std::string dict = test::readFile(std::filesystem::path(test::kSourceDir) / "fuzz/project.dict");
    ASSERT_FALSE(dict.empty());
    for (const std::string& name : scene::sceneFieldNames())
        EXPECT_NE(dict.find("\n\"\\\"" + name + "\\\"\"\n"), std::string::npos)
            << "fuzz/project.dict lacks the line \"\\\"" << name << "\\\"\"";
}

// docs/project-format.md's field tables are the generated text between
// "<!-- scene-fields NAME -->" and "<!-- /scene-fields -->". When they
// differ, the doc as it should be is written beside the build, to copy over.
TEST(SceneFields, FormatDocsTablesAreGeneratedFromTheTables) {
    const std::string doc =
        test::readFile(std::filesystem::path(test::kSourceDir) / "docs/project-format.md");
    ASSERT_FALSE(doc.empty());
    std::string current = doc;
    for (const char* table : {"sky", "material", "object", "light", "camera", "cameraPath"}) {
        const std::string open = std::string("<!-- scene-fields ") + table + " -->\n";
        const std::size_t start = current.find(open);
        ASSERT_NE(start, std::string::npos) << "no " << open << "in docs/project-format.md";
        const std::size_t end = current.find("<!-- /scene-fields -->", start);
        ASSERT_NE(end, std::string::npos);
        current.replace(start + open.size(), end - start - open.size(), scene::sceneFieldsMarkdown(table));
    }
    if (current != doc) {
        const std::filesystem::path fixed =
            std::filesystem::path(test::kBinaryDir) / "project-format.generated.md";
        test::writeFile(fixed, current);
        ADD_FAILURE() << "docs/project-format.md's field tables differ from SceneFields.h; the doc with the "
                         "generated tables is "
                      << fixed;
    }
}
