// The generator of C++ mirrors of GLSL blocks (tools/shader_structs) held against facts it does not
// produce: shaders/tests/shader_structs_probe.comp's blocks against offsets derived by hand from
// the std430 (push constants) and std140 (uniform blocks) rules, and against SPIRV-Cross's
// reflection of the compiled module; the generator run again gives the same bytes; a layout no C++
// type mirrors is refused with the shader, the block and the member named.
#include <shader_structs/godrays/godray_lines.comp.hpp>
#include <shader_structs/tests/shader_structs_probe.comp.hpp>

#include <gtest/gtest.h>
#include <spirv_cross/spirv_cross_c.h>

#include <sys/wait.h>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace vkw::test {
namespace {

namespace probe = vkw::glsl::shader_structs_probe_comp;
namespace fs = std::filesystem;

// The push block, std430. Alignments: 4 for 32-bit scalars, 8 for uint64_t and vec2/ivec2, 16 for
// vec3/vec4; an array's stride is its element's size rounded up to its alignment (float[3]: 4); a
// struct aligns to its most aligned member (Inner: 16, its vec3).
//   count     uint      0
//   delta     int       4
//   flag      bool      8    a uint in a block
//   direction vec3      16   aligned up from 12: bytes 12..16 are padding
//   range     float     28   in the vec3's tail (16 + 12)
//   uv        vec2      32
//   key       uint64_t  40
//   weights   float[3]  48   stride 4, to 60
//   inner     Inner     64   aligned up from 60 to 16; Inner: normal (vec3) at 0, bias at 12, 16 bytes
//   texel     ivec2     80
//   new       uint      88   a C++ keyword: the mirror names it new_
//   last      float     92
// The block's declared size is the end of its last member, 96, with no tail padding.
TEST(ShaderStructs, ProbePushBlockHasTheStd430Offsets) {
    EXPECT_EQ(offsetof(probe::Push, count), 0u);
    EXPECT_EQ(offsetof(probe::Push, delta), 4u);
    EXPECT_EQ(offsetof(probe::Push, flag), 8u);
    EXPECT_EQ(offsetof(probe::Push, direction), 16u);
    EXPECT_EQ(offsetof(probe::Push, range), 28u);
    EXPECT_EQ(offsetof(probe::Push, uv), 32u);
    EXPECT_EQ(offsetof(probe::Push, key), 40u);
    EXPECT_EQ(offsetof(probe::Push, weights), 48u);
    EXPECT_EQ(sizeof(probe::Push::weights), 12u);
    EXPECT_EQ(offsetof(probe::Push, inner), 64u);
    EXPECT_EQ(offsetof(probe::Inner, normal), 0u);
    EXPECT_EQ(offsetof(probe::Inner, bias), 12u);
    EXPECT_EQ(sizeof(probe::Inner), 16u);
    EXPECT_EQ(offsetof(probe::Push, texel), 80u);
    EXPECT_EQ(offsetof(probe::Push, new_), 88u);
    EXPECT_EQ(offsetof(probe::Push, last), 92u);
    EXPECT_EQ(sizeof(probe::Push), 96u);
    // The C++ types: bool as uint32_t, the 64-bit member as uint64_t, glm's vectors.
    static_assert(std::is_same_v<decltype(probe::Push::flag), uint32_t>);
    static_assert(std::is_same_v<decltype(probe::Push::key), uint64_t>);
    static_assert(std::is_same_v<decltype(probe::Push::direction), glm::vec3>);
    static_assert(std::is_same_v<decltype(probe::Push::texel), glm::ivec2>);
    static_assert(std::is_same_v<decltype(probe::Push::delta), int32_t>);
}

// The uniform block Probe, std140: as std430, except that an array's stride and a struct's
// alignment are rounded up to 16, and the member after a struct starts at a multiple of 16.
//   transform mat4      0    four vec4 columns, 64 bytes
//   position  vec3      64
//   radius    float     76   in the vec3's tail
//   samples   float[4]  80   stride 16 (4 rounded up to 16), to 144: each a float_stride16
//   enabled   bool      144  a uint
//   mode      int       148
//   ids       uvec2     152
//   lights    Light[2]  160  Light: colour (vec3) 0, power 12, offset (vec2) 16, 24 bytes, aligned
//                            to 16, so stride 32 (each a Light_stride32), to 224
//   sun       Light     224  its 24 bytes end at 248
//   tail      float     256  248 rounded up to 16 after the struct
// The declared size ends at 260; a std140 block's size is rounded up to 16: 272.
TEST(ShaderStructs, ProbeUniformBlockHasTheStd140Offsets) {
    EXPECT_EQ(offsetof(probe::Probe, transform), 0u);
    EXPECT_EQ(offsetof(probe::Probe, position), 64u);
    EXPECT_EQ(offsetof(probe::Probe, radius), 76u);
    EXPECT_EQ(offsetof(probe::Probe, samples), 80u);
    EXPECT_EQ(sizeof(probe::Probe::samples), 64u);
    EXPECT_EQ(sizeof(probe::float_stride16), 16u);
    EXPECT_EQ(offsetof(probe::float_stride16, value), 0u);
    EXPECT_EQ(offsetof(probe::Probe, enabled), 144u);
    EXPECT_EQ(offsetof(probe::Probe, mode), 148u);
    EXPECT_EQ(offsetof(probe::Probe, ids), 152u);
    EXPECT_EQ(offsetof(probe::Probe, lights), 160u);
    EXPECT_EQ(sizeof(probe::Light_stride32), 32u);
    EXPECT_EQ(offsetof(probe::Light_stride32, value), 0u);
    EXPECT_EQ(sizeof(probe::Light), 24u);
    EXPECT_EQ(offsetof(probe::Light, colour), 0u);
    EXPECT_EQ(offsetof(probe::Light, power), 12u);
    EXPECT_EQ(offsetof(probe::Light, offset), 16u);
    EXPECT_EQ(offsetof(probe::Probe, sun), 224u);
    EXPECT_EQ(offsetof(probe::Probe, tail), 256u);
    EXPECT_EQ(sizeof(probe::Probe), 272u);
    EXPECT_EQ(sizeof(probe::Scale), 16u);
    static_assert(std::is_same_v<decltype(probe::Probe::transform), glm::mat4>);
    static_assert(std::is_same_v<decltype(probe::Probe::enabled), uint32_t>);

    // The element wrappers place each element at its stride.
    probe::Probe block;
    const auto* base = reinterpret_cast<const unsigned char*>(&block);
    EXPECT_EQ(reinterpret_cast<const unsigned char*>(&block.samples[3].value) - base, 80 + 3 * 16);
    EXPECT_EQ(reinterpret_cast<const unsigned char*>(&block.lights[1].value.offset) - base, 160 + 32 + 16);
    // Every member and padding byte starts zeroed.
    EXPECT_EQ(block.samples[2].value, 0.0f);
    EXPECT_EQ(block.lights[1].value.power, 0.0f);
}

// godray_lines.comp's push block: grid, per_pixel_medium (uint), max_amplitude (float), levels
// (int), 4 bytes each at 0, 4, 8, 12: 16 bytes, the size GodrayLinesPush pushes.
TEST(ShaderStructs, GodrayLinesPushIsItsFourScalars) {
    namespace lines = vkw::glsl::godray_lines_comp;
    EXPECT_EQ(sizeof(lines::Push), 16u);
    EXPECT_EQ(offsetof(lines::Push, grid), 0u);
    EXPECT_EQ(offsetof(lines::Push, per_pixel_medium), 4u);
    EXPECT_EQ(offsetof(lines::Push, max_amplitude), 8u);
    EXPECT_EQ(offsetof(lines::Push, levels), 12u);
}

// A compiled module reflected by SPIRV-Cross: each block's declared size and its members' offsets
// by name.
struct ReflectedBlock {
    size_t declared_size = 0;
    std::map<std::string, uint32_t> offsets;
};

class Reflection {
public:
    explicit Reflection(const std::string& shader) {
        const fs::path path = fs::path(VKWATER_TEST_SHADER_DIR) / shader;
        std::ifstream in(path, std::ios::binary | std::ios::ate);
        if (!in) throw std::runtime_error(path.string() + " is not built");
        std::vector<uint32_t> words(static_cast<size_t>(in.tellg()) / 4);
        in.seekg(0);
        in.read(reinterpret_cast<char*>(words.data()), static_cast<std::streamsize>(words.size() * 4));
        spvc_parsed_ir ir = nullptr;
        if (spvc_context_create(&context_) != SPVC_SUCCESS ||
            spvc_context_parse_spirv(context_, words.data(), words.size(), &ir) != SPVC_SUCCESS ||
            spvc_context_create_compiler(context_, SPVC_BACKEND_NONE, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP,
                                         &compiler_) != SPVC_SUCCESS ||
            spvc_compiler_create_shader_resources(compiler_, &resources_) != SPVC_SUCCESS) {
            throw std::runtime_error("SPIRV-Cross could not reflect " + path.string());
        }
    }
    ~Reflection() { spvc_context_destroy(context_); }
    Reflection(const Reflection&) = delete;
    Reflection& operator=(const Reflection&) = delete;

    // The push-constant block, or the uniform block whose type is `name`.
    ReflectedBlock block(spvc_resource_type kind, const std::string& name = "") const {
        const spvc_reflected_resource* list = nullptr;
        size_t count = 0;
        spvc_resources_get_resource_list_for_type(resources_, kind, &list, &count);
        for (size_t i = 0; i < count; ++i) {
            if (!name.empty() && spvc_compiler_get_name(compiler_, list[i].base_type_id) != name) continue;
            const spvc_type type = spvc_compiler_get_type_handle(compiler_, list[i].base_type_id);
            ReflectedBlock block;
            spvc_compiler_get_declared_struct_size(compiler_, type, &block.declared_size);
            for (unsigned m = 0; m < spvc_type_get_num_member_types(type); ++m) {
                unsigned offset = 0;
                spvc_compiler_type_struct_member_offset(compiler_, type, m, &offset);
                block.offsets[spvc_compiler_get_member_name(compiler_, list[i].base_type_id, m)] = offset;
            }
            return block;
        }
        throw std::runtime_error("no block '" + name + "'");
    }

private:
    spvc_context context_ = nullptr;
    spvc_compiler compiler_ = nullptr;
    spvc_resources resources_ = nullptr;
};

#define VKWATER_OFFSET(S, member) \
    std::pair<std::string, size_t> { #member, offsetof(S, member) }

TEST(ShaderStructs, ProbeMirrorsAgreeWithSpirvCrossReflection) {
    const Reflection reflection("tests/shader_structs_probe.comp.spv");
    // A push struct is exactly the block's declared size: PassContext::push_constants pushes
    // sizeof(struct) bytes and requires the longest block's size.
    const ReflectedBlock push = reflection.block(SPVC_RESOURCE_TYPE_PUSH_CONSTANT);
    EXPECT_EQ(sizeof(probe::Push), push.declared_size);
    const std::vector<std::pair<std::string, size_t>> push_members = {
        VKWATER_OFFSET(probe::Push, count), VKWATER_OFFSET(probe::Push, delta),
        VKWATER_OFFSET(probe::Push, flag),  VKWATER_OFFSET(probe::Push, direction),
        VKWATER_OFFSET(probe::Push, range), VKWATER_OFFSET(probe::Push, uv),
        VKWATER_OFFSET(probe::Push, key),   VKWATER_OFFSET(probe::Push, weights),
        VKWATER_OFFSET(probe::Push, inner), VKWATER_OFFSET(probe::Push, texel),
        VKWATER_OFFSET(probe::Push, last),
    };
    ASSERT_EQ(push.offsets.size(), push_members.size() + 1);  // and `new`
    for (const auto& [name, offset] : push_members) EXPECT_EQ(push.offsets.at(name), offset) << name;
    EXPECT_EQ(push.offsets.at("new"), offsetof(probe::Push, new_));

    // A uniform struct is the declared size rounded up to 16.
    const ReflectedBlock uniform = reflection.block(SPVC_RESOURCE_TYPE_UNIFORM_BUFFER, "Probe");
    EXPECT_EQ(uniform.declared_size, 260u);
    EXPECT_EQ(sizeof(probe::Probe), (uniform.declared_size + 15) / 16 * 16);
    const std::vector<std::pair<std::string, size_t>> uniform_members = {
        VKWATER_OFFSET(probe::Probe, transform), VKWATER_OFFSET(probe::Probe, position),
        VKWATER_OFFSET(probe::Probe, radius),    VKWATER_OFFSET(probe::Probe, samples),
        VKWATER_OFFSET(probe::Probe, enabled),   VKWATER_OFFSET(probe::Probe, mode),
        VKWATER_OFFSET(probe::Probe, ids),       VKWATER_OFFSET(probe::Probe, lights),
        VKWATER_OFFSET(probe::Probe, sun),       VKWATER_OFFSET(probe::Probe, tail),
    };
    ASSERT_EQ(uniform.offsets.size(), uniform_members.size());
    for (const auto& [name, offset] : uniform_members) EXPECT_EQ(uniform.offsets.at(name), offset) << name;
    EXPECT_EQ(sizeof(probe::Scale), reflection.block(SPVC_RESOURCE_TYPE_UNIFORM_BUFFER, "Scale").declared_size);
}

TEST(ShaderStructs, GodrayLinesPushIsItsDeclaredSize) {
    const Reflection reflection("godrays/godray_lines.comp.spv");
    EXPECT_EQ(sizeof(vkw::glsl::godray_lines_comp::Push),
              reflection.block(SPVC_RESOURCE_TYPE_PUSH_CONSTANT).declared_size);
}

std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

struct ToolRun {
    int status = -1;
    std::string output;  // stdout and stderr
};

// `shared`: the --shared arguments (SPV, under the shader directory, and its shader), if any.
// `spvs`: the shader's compiled variants, under the shader directory.
ToolRun run_tool(const std::vector<std::string>& spvs, const fs::path& out, const std::string& shader,
                 const std::pair<std::string, std::string>& shared = {}) {
    std::string command = std::string("'") + VKWATER_SHADER_STRUCTS_TOOL + "' '" + out.string() + "' " + shader;
    for (const std::string& spv : spvs) command += std::string(" '") + VKWATER_TEST_SHADER_DIR + "/" + spv + "'";
    if (!shared.first.empty()) {
        command += std::string(" --shared '") + VKWATER_TEST_SHADER_DIR + "/" + shared.first + "' " + shared.second;
    }
    command += " 2>&1";
    ToolRun run;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return run;
    char buffer[256];
    while (fgets(buffer, sizeof(buffer), pipe)) run.output += buffer;
    const int status = pclose(pipe);
    run.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return run;
}

// The header in the build tree is what the generator writes now, byte for byte, every run; and
// the blocks come in binding order (Probe at 1, Scale at 3, though Scale is declared first), then
// the push block.
TEST(ShaderStructs, GeneratorIsDeterministic) {
    const fs::path built = fs::path(VKWATER_SHADER_STRUCTS_DIR) / "tests/shader_structs_probe.comp.hpp";
    const std::string expected = read_text(built);
    ASSERT_FALSE(expected.empty()) << built << " is not generated";
    for (int run = 0; run < 2; ++run) {
        const fs::path out = fs::path(testing::TempDir()) / ("shader_structs_probe_" + std::to_string(run) + ".hpp");
        fs::remove(out);
        const ToolRun result =
            run_tool({"tests/shader_structs_probe.comp.spv"}, out, "tests/shader_structs_probe.comp");
        ASSERT_EQ(result.status, 0) << result.output;
        EXPECT_EQ(read_text(out), expected) << "run " << run;
        fs::remove(out);
    }
    EXPECT_EQ(expected.rfind("// Generated by tools/shader_structs from shaders/tests/shader_structs_probe.comp", 0),
              0u);
    const size_t probe_at = expected.find("\nstruct Probe {"), scale_at = expected.find("\nstruct Scale {");
    const size_t push_at = expected.find("\nstruct Push {");
    ASSERT_NE(probe_at, std::string::npos);
    EXPECT_LT(probe_at, scale_at);
    EXPECT_LT(scale_at, push_at);
    EXPECT_NE(push_at, std::string::npos);
}

// A std140 mat3 has columns 16 bytes apart; glm::mat3's are 12. The generator refuses it and names
// the shader, the block and the member, and writes nothing.
TEST(ShaderStructs, GeneratorRefusesALayoutGlmCannotMirror) {
    const fs::path out = fs::path(testing::TempDir()) / "shader_structs_refused.hpp";
    fs::remove(out);
    const ToolRun result =
        run_tool({"tests/shader_structs_refused.comp.spv"}, out, "tests/shader_structs_refused.comp");
    EXPECT_EQ(result.status, 1) << result.output;
    EXPECT_NE(result.output.find("shader 'tests/shader_structs_refused.comp', block 'Refused', member 'basis': mat3 "
                                 "with a column stride of 16 bytes"),
              std::string::npos)
        << result.output;
    EXPECT_FALSE(fs::exists(out));
}

// A struct named like one of the shared shader's but laid out differently cannot be one C++ type:
// the generator refuses it, naming the struct and the shared shader, and writes nothing. (The probe's
// push block is `Push`, 16 bytes at most; the photon kernel's `Push` is 128.)
TEST(ShaderStructs, GeneratorRefusesASharedNameWithAnotherLayout) {
    const fs::path out = fs::path(testing::TempDir()) / "shader_structs_probe_shared.hpp";
    fs::remove(out);
    const ToolRun result =
        run_tool({"tests/shader_structs_probe.comp.spv"}, out, "tests/shader_structs_probe.comp",
                 {"caustics/caustic_photons.comp.bilinear_shadow.spv", "caustics/caustic_photons.comp"});
    EXPECT_EQ(result.status, 1) << result.output;
    EXPECT_NE(result.output.find("struct 'Push' is laid out differently here than in shaders/caustics/"
                                 "caustic_photons.comp, whose C++ type every shader shares"),
              std::string::npos)
        << result.output;
    EXPECT_FALSE(fs::exists(out));
}

// With a shared shader whose structs it also declares, identically, the header aliases them and
// includes the shared header: the photon kernel against the camera-space splat kernel, which share
// the photon source and the light space (their `Push` blocks differ, so the splats' kernel is the
// subject and common/shared_blocks.comp, which has no push block, the shared shader).
TEST(ShaderStructs, GeneratorAliasesTheSharedStructs) {
    const fs::path out = fs::path(testing::TempDir()) / "shader_structs_splats_shared.hpp";
    fs::remove(out);
    const ToolRun result =
        run_tool({"caustics/caustic_camera_splats.comp.shadow.spv"}, out, "caustics/caustic_camera_splats.comp",
                 {"common/shared_blocks.comp.spv", "common/shared_blocks.comp"});
    ASSERT_EQ(result.status, 0) << result.output;
    const std::string text = read_text(out);
    EXPECT_NE(text.find("#include <shader_structs/common/shared_blocks.comp.hpp>"), std::string::npos) << text;
    for (const char* name : {"CausticLightSpace", "CausticPhotonSource", "SunShadowSpace", "ShadowProjection"}) {
        EXPECT_NE(text.find(std::string("using ") + name + " = ::vkw::glsl::shared_blocks_comp::" + name + ";"),
                  std::string::npos)
            << name;
        EXPECT_EQ(text.find(std::string("struct ") + name + " {"), std::string::npos) << name;
    }
    EXPECT_NE(text.find("struct Push {"), std::string::npos);
    fs::remove(out);
}

// A shader's header holds the blocks of all the variants it is given: the photon kernel's plain
// variant declares no sun shadow block, its shadow variant does, and the two together give both
// the push block and the shadow's. A file that is no variant of the shader is refused.
TEST(ShaderStructs, GeneratorTakesTheUnionOfTheVariants) {
    const fs::path out = fs::path(testing::TempDir()) / "shader_structs_photons.hpp";
    const std::string shader = "caustics/caustic_photons.comp";
    const auto has = [](const std::string& text, const std::string& what) {
        return text.find(what) != std::string::npos;
    };
    fs::remove(out);
    ToolRun result = run_tool({"caustics/caustic_photons.comp.bilinear.spv"}, out, shader);
    ASSERT_EQ(result.status, 0) << result.output;
    std::string text = read_text(out);
    EXPECT_TRUE(has(text, "struct Push {"));
    EXPECT_FALSE(has(text, "SunShadowSpace"));

    result =
        run_tool({"caustics/caustic_photons.comp.bilinear.spv", "caustics/caustic_photons.comp.bilinear_shadow.spv"},
                 out, shader);
    ASSERT_EQ(result.status, 0) << result.output;
    text = read_text(out);
    EXPECT_TRUE(has(text, "struct Push {"));
    EXPECT_TRUE(has(text, "struct SunShadowSpace {"));
    EXPECT_TRUE(has(text, "// The union of the blocks of its variants: bilinear bilinear_shadow."));

    result = run_tool({"godrays/godray_blur.comp.spv"}, out, shader);
    EXPECT_EQ(result.status, 1) << result.output;
    EXPECT_TRUE(has(result.output, "godray_blur.comp.spv is no compiled variant of caustics/caustic_photons.comp"))
        << result.output;
    fs::remove(out);
}

}  // namespace
}  // namespace vkw::test
