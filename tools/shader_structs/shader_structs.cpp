// vkwater_shader_structs: the C++ mirror of a compiled shader's push-constant block and of every
// uniform block it declares, as one generated header (docs/architecture.md, "Generated mirrors of
// GLSL blocks").
//
//   vkwater_shader_structs OUT SHADER SPV... [--shared SHARED_SPV SHARED_SHADER]
//
// reads each SPV (SHADER compiled, once per variant: <name>[.<variant>].spv), and writes OUT:
// namespace vkw::glsl::<SHADER's file name, '.' as '_'> holding a struct per block any variant
// declares and per struct type the blocks' members use, with the GLSL names, explicit padding
// members wherever the GLSL offsets leave a gap, and a static_assert of every size and offset. A
// block two variants declare with different layouts is refused. SHADER (e.g.
// "godrays/godray_blur.comp") and the variants name the source in the header's first line. OUT is
// rewritten only when its text changes, so a rebuild that changes nothing recompiles nothing. A
// layout that no C++ type mirrors exactly is refused with an error that names the shader, the block
// and the member; the exit status is then 1.
//
// --shared names the shader whose structs are the C++ types many shaders share
// (common/shared_blocks.comp): a struct of SPV with the name of one of its structs and the same
// layout is not defined again but aliased to it (`using WaterGrid = vkw::glsl::shared_blocks_comp::
// WaterGrid;`), so that one C++ type fills the block of every shader that declares it. The same
// name with another layout is refused: the C++ could not share it.
#include <spirv_cross/spirv_cross_c.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace {

struct GeneratorError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// One member of a generated struct: a GLSL member, or explicit padding (`padding` true).
struct Member {
    std::string name;
    std::string type;     // the C++ type, without the array extent
    uint32_t count = 0;   // array elements; 0: not an array
    uint32_t offset = 0;  // bytes from the start of the struct
    uint32_t size = 0;    // bytes, the whole array for an array
    std::string glsl;     // the GLSL type, for the comment
    bool padding = false;
    bool struct_type = false;  // `type` is a struct of this header (qualified where a member's name hides it)
};

struct StructDef {
    std::string name;
    std::string note;  // the comment above it
    std::vector<Member> members;
    uint32_t size = 0;
    uint32_t align = 4;
    std::string origin;   // the block it was first met in, for messages
    bool shared = false;  // an alias of the shared shader's struct of this name
};

// The structs of the shader named by --shared, and where the generated C++ finds them.
struct SharedStructs {
    std::string shader;  // e.g. "common/shared_blocks.comp"
    std::string ns;      // its header's namespace
    std::map<std::string, StructDef> structs;
};

// A C++ type with its size and alignment, as the generated header spells it.
struct CppType {
    std::string name;
    std::string glsl;
    uint32_t size = 0;
    uint32_t align = 4;
    bool struct_type = false;
};

// Names that GLSL allows but C++ reserves or that name the types and namespaces the header uses
// (a member so named would hide them from the members after it): such a member gets a trailing '_'.
const char* const kCppReserved =
    " alignas alignof and and_eq asm auto bitand bitor catch char char8_t char16_t char32_t class compl concept"
    " consteval constexpr constinit const_cast co_await co_return co_yield decltype delete double dynamic_cast enum"
    " explicit export extern false friend goto inline long mutable namespace new noexcept not not_eq nullptr operator"
    " or or_eq private protected public register reinterpret_cast requires short signed sizeof static static_assert"
    " static_cast template this thread_local throw true try typedef typeid typename union unsigned using virtual"
    " volatile wchar_t xor xor_eq int8_t int16_t int32_t int64_t uint8_t uint16_t uint32_t uint64_t glm std vkw"
    " offsetof ";

std::string cpp_identifier(const std::string& glsl) {
    return std::string(kCppReserved).find(" " + glsl + " ") != std::string::npos ? glsl + "_" : glsl;
}

uint32_t round_up(uint32_t value, uint32_t multiple) { return (value + multiple - 1) / multiple * multiple; }

class Generator {
public:
    Generator(std::string shader, std::string ns, const SharedStructs* shared = nullptr)
        : source_(std::move(shader)), ns_(std::move(ns)), shared_(shared) {}

    const std::map<std::string, StructDef>& structs() const { return structs_; }

    // Adds the blocks of one compiled variant (`variant` empty: the shader has none): every uniform
    // block in (set, binding) order, then the push-constant block. A block or struct the variants
    // before it declared is the same struct if its layout is; else the header could not name both.
    void run(spvc_compiler compiler, const std::string& variant) {
        compiler_ = compiler;
        shader_ = source_ + (variant.empty() ? "" : " (variant " + variant + ")");
        if (!variant.empty()) variants_.push_back(variant);
        spvc_resources resources = nullptr;
        check(spvc_compiler_create_shader_resources(compiler_, &resources), "list its resources");
        struct Block {
            uint32_t set, binding;
            spvc_type_id type;
            std::string name;
        };
        std::vector<Block> uniforms;
        const spvc_reflected_resource* list = nullptr;
        size_t count = 0;
        check(spvc_resources_get_resource_list_for_type(resources, SPVC_RESOURCE_TYPE_UNIFORM_BUFFER, &list, &count),
              "list its uniform blocks");
        for (size_t i = 0; i < count; ++i) {
            uniforms.push_back({spvc_compiler_get_decoration(compiler_, list[i].id, SpvDecorationDescriptorSet),
                                spvc_compiler_get_decoration(compiler_, list[i].id, SpvDecorationBinding),
                                list[i].base_type_id, type_name(list[i].base_type_id, list[i].name)});
        }
        std::sort(uniforms.begin(), uniforms.end(), [](const Block& a, const Block& b) {
            return std::tie(a.set, a.binding, a.name) < std::tie(b.set, b.binding, b.name);
        });
        for (const Block& block : uniforms) {
            const std::string note = "layout(set = " + std::to_string(block.set) +
                                     ", binding = " + std::to_string(block.binding) + ") uniform " + block.name;
            add_block(block.type, block.name, note, /*uniform=*/true);
        }
        check(spvc_resources_get_resource_list_for_type(resources, SPVC_RESOURCE_TYPE_PUSH_CONSTANT, &list, &count),
              "list its push constants");
        for (size_t i = 0; i < count; ++i) {
            const std::string name = type_name(list[i].base_type_id, list[i].name);
            add_block(list[i].base_type_id, name, "layout(push_constant) uniform " + name, /*uniform=*/false);
        }
    }

    std::string header() const {
        std::ostringstream out;
        out << "// Generated by tools/shader_structs from shaders/" << source_ << "; do not edit.\n";
        if (!variants_.empty()) {
            out << "// The union of the blocks of its variants:";
            for (const std::string& v : variants_) out << " " << v;
            out << ".\n";
        }
        out << "// The C++ mirrors of its push-constant and uniform blocks, member for member at the GLSL\n";
        out << "// offsets (pad_<offset> fills a gap); each static_assert fails the build on a drift.\n";
        out << "#pragma once\n\n";
        const bool aliases = std::any_of(order_.begin(), order_.end(), [](const StructDef& d) { return d.shared; });
        if (aliases) out << "#include <shader_structs/" << shared_->shader << ".hpp>\n\n";
        out << "#include <glm/glm.hpp>\n\n#include <cstddef>\n#include <cstdint>\n\n";
        out << "namespace " << ns_ << " {\n";
        for (const StructDef& def : order_) write_struct(out, def);
        out << "\n}  // namespace " << ns_ << "\n";
        return out.str();
    }

private:
    [[noreturn]] void fail(const std::string& where, const std::string& what) const {
        throw GeneratorError("shader '" + shader_ + "'" + (where.empty() ? "" : ", " + where) + ": " + what);
    }
    void check(spvc_result result, const std::string& what) const {
        if (result != SPVC_SUCCESS) fail("", "SPIRV-Cross could not " + what);
    }

    std::string type_name(spvc_type_id id, const char* fallback) const {
        const char* name = spvc_compiler_get_name(compiler_, id);
        if (name && *name) return name;
        if (fallback && *fallback) return fallback;
        fail("", "a block or struct type without a name (was the SPIR-V stripped?)");
    }

    void add_block(spvc_type_id type_id, const std::string& name, const std::string& note, bool uniform) {
        const spvc_type type = spvc_compiler_get_type_handle(compiler_, type_id);
        size_t declared = 0;
        check(spvc_compiler_get_declared_struct_size(compiler_, type, &declared), "size block '" + name + "'");
        // A push-constant block is exactly its declared size: the pass pushes sizeof(struct) bytes,
        // which must equal the longest stage's block (engine/framegraph/pass_context.cpp). A std140
        // uniform block's size is rounded up to its base alignment, 16 (the block's tail padding).
        const uint32_t size = uniform ? round_up(static_cast<uint32_t>(declared), 16) : static_cast<uint32_t>(declared);
        const std::string size_note = uniform && size != declared
                                          ? std::to_string(declared) + " bytes declared, " + std::to_string(size) +
                                                " with the std140 tail to a multiple of 16"
                                          : std::to_string(size) + " bytes, the declared size";
        build_struct(type_id, name, note + ": " + size_note, size, "block '" + name + "'");
    }

    // The struct for SPIR-V struct type `id` named `name`, `size` bytes (at least its declared
    // size), defined after the types its members use. A second SPIR-V type of the same name (glslang
    // makes one per layout) is the same struct if its layout is; else the header could not name both.
    const StructDef& build_struct(spvc_type_id id, const std::string& name, const std::string& note, uint32_t size,
                                  const std::string& where) {
        const spvc_type type = spvc_compiler_get_type_handle(compiler_, id);
        StructDef def;
        def.name = name;
        def.note = note;
        def.origin = where;
        uint32_t cursor = 0;
        std::set<std::string> names;
        const unsigned member_count = spvc_type_get_num_member_types(type);
        for (unsigned i = 0; i < member_count; ++i) {
            const char* raw = spvc_compiler_get_member_name(compiler_, id, i);
            const std::string glsl_name = raw && *raw ? raw : "member" + std::to_string(i);
            const std::string member_where = where + ", member '" + glsl_name + "'";
            unsigned offset = 0;
            check(spvc_compiler_type_struct_member_offset(compiler_, type, i, &offset),
                  "read the offset of " + member_where);
            if (spvc_compiler_has_member_decoration(compiler_, id, i, SpvDecorationRowMajor)) {
                fail(member_where, "a row_major matrix; glm's matrices are column-major");
            }
            Member member = mirror_member(type, i, member_where);
            member.name = cpp_identifier(glsl_name);
            member.offset = offset;
            size_t declared_member = 0;
            check(spvc_compiler_get_declared_struct_member_size(compiler_, type, i, &declared_member),
                  "size " + member_where);
            if (member.size != declared_member) {
                fail(member_where, "the C++ " + member.type + " is " + std::to_string(member.size) +
                                       " bytes but the member is " + std::to_string(declared_member));
            }
            if (offset < cursor) {
                fail(member_where, "offset " + std::to_string(offset) +
                                       " lies inside the member before it (which ends at " + std::to_string(cursor) +
                                       ")");
            }
            const uint32_t member_align = member.struct_type ? structs_.at(member.type).align : align_of(member);
            if (offset % member_align != 0) {
                fail(member_where, "offset " + std::to_string(offset) + " is not a multiple of the C++ " + member.type +
                                       "'s alignment " + std::to_string(member_align));
            }
            if (offset > cursor) def.members.push_back(padding(cursor, offset - cursor));
            def.align = std::max(def.align, member_align);
            cursor = offset + member.size;
            names.insert(member.name);
            def.members.push_back(member);
        }
        if (size < cursor) fail(where, "its size " + std::to_string(size) + " ends inside its last member");
        if (size > cursor) def.members.push_back(padding(cursor, size - cursor));
        def.size = size;
        if (size % def.align != 0) {
            fail(where, std::to_string(size) + " bytes is not a multiple of the C++ struct's alignment " +
                            std::to_string(def.align) + " (a 64-bit member): C++ would add tail padding");
        }
        // A padding name that a GLSL member already has gets a trailing '_'.
        for (Member& m : def.members) {
            while (m.padding && names.count(m.name)) m.name += "_";
        }
        return add_struct(std::move(def));
    }

    const StructDef& add_struct(StructDef def) {
        const auto found = structs_.find(def.name);
        if (found != structs_.end()) {
            if (!same_layout(found->second, def)) {
                fail(def.origin,
                     "struct '" + def.name + "' is laid out differently here than in " + found->second.origin +
                         " (glslang makes one type per block layout); give the two uses different GLSL types");
            }
            return found->second;
        }
        const StructDef* shared = find_shared(def.name);
        if (shared) {
            if (!same_layout(*shared, def)) {
                fail(def.origin, "struct '" + def.name + "' is laid out differently here than in shaders/" +
                                     shared_->shader +
                                     ", whose C++ type every shader shares; give it another GLSL name");
            }
            def.shared = true;
        }
        order_.push_back(def);
        return structs_.emplace(def.name, std::move(def)).first->second;
    }

    const StructDef* find_shared(const std::string& name) const {
        if (!shared_) return nullptr;
        const auto found = shared_->structs.find(name);
        return found == shared_->structs.end() ? nullptr : &found->second;
    }

    static bool same_layout(const StructDef& a, const StructDef& b) {
        if (a.size != b.size || a.members.size() != b.members.size()) return false;
        for (size_t i = 0; i < a.members.size(); ++i) {
            const Member& x = a.members[i];
            const Member& y = b.members[i];
            if (x.name != y.name || x.type != y.type || x.count != y.count || x.offset != y.offset) return false;
        }
        return true;
    }

    static Member padding(uint32_t offset, uint32_t bytes) {
        Member m;
        m.name = "pad_" + std::to_string(offset);
        m.type = "uint8_t";
        m.count = bytes;
        m.offset = offset;
        m.size = bytes;
        m.padding = true;
        return m;
    }

    uint32_t align_of(const Member& m) const {
        if (m.struct_type) return structs_.at(m.type).align;
        return m.type == "uint64_t" || m.type == "int64_t" || m.type == "double" ? 8 : 4;
    }

    // Member `index` of struct `parent`: its C++ type and array extent.
    Member mirror_member(spvc_type parent, unsigned index, const std::string& where) {
        const spvc_type_id type_id = spvc_type_get_member_type(parent, index);
        const spvc_type type = spvc_compiler_get_type_handle(compiler_, type_id);
        Member m;
        const unsigned dims = spvc_type_get_num_array_dimensions(type);
        if (dims == 0) {
            const CppType element = element_type(type, parent, index, where);
            m.type = element.name;
            m.glsl = element.glsl;
            m.size = element.size;
            m.struct_type = element.struct_type;
            return m;
        }
        if (dims > 1) fail(where, "an array of arrays; the generator mirrors one dimension");
        if (!spvc_type_array_dimension_is_literal(type, 0)) {
            fail(where, "an array sized by a specialization constant; its C++ size is not known when generating");
        }
        const uint32_t count = spvc_type_get_array_dimension(type, 0);
        if (count == 0) fail(where, "a runtime-sized array");
        unsigned stride = 0;
        check(spvc_compiler_type_struct_member_array_stride(compiler_, parent, index, &stride),
              "read the array stride of " + where);
        const CppType element = element_type(type, parent, index, where);
        m.count = count;
        m.size = stride * count;
        m.glsl = element.glsl + "[" + std::to_string(count) + "]";
        if (element.size == stride) {
            m.type = element.name;
            m.struct_type = element.struct_type;
            return m;
        }
        if (element.size > stride) {
            fail(where, "array stride " + std::to_string(stride) + " is less than its element's " +
                            std::to_string(element.size) + " bytes");
        }
        // A stride beyond the element (std140's float[N] at 16 bytes each, a struct's array
        // rounded up to its alignment): an element wrapper whose tail padding makes up the stride,
        // `value` holding the element.
        m.type = wrapper(element, stride, where).name;
        m.struct_type = true;
        return m;
    }

    const StructDef& wrapper(const CppType& element, uint32_t stride, const std::string& where) {
        std::string base = element.glsl;
        std::replace(base.begin(), base.end(), ' ', '_');
        StructDef def;
        def.name = base + "_stride" + std::to_string(stride);
        def.note = "an element of a " + element.glsl + " array of stride " + std::to_string(stride) +
                   ": the element, then padding to the stride";
        def.origin = where;
        Member value;
        value.name = "value";
        value.type = element.name;
        value.glsl = element.glsl;
        value.size = element.size;
        value.struct_type = element.struct_type;
        def.members.push_back(value);
        def.members.push_back(padding(element.size, stride - element.size));
        def.size = stride;
        def.align = element.align;
        if (stride % element.align != 0) {
            fail(where, "array stride " + std::to_string(stride) + " is not a multiple of its element's alignment");
        }
        return add_struct(std::move(def));
    }

    // The C++ type of one element of member `index` of `parent` (the member itself if it is no
    // array); a struct is its declared size, the end of its last member.
    CppType element_type(spvc_type type, spvc_type parent, unsigned index, const std::string& where) {
        const spvc_basetype base = spvc_type_get_basetype(type);
        const unsigned vecsize = spvc_type_get_vector_size(type);
        const unsigned columns = spvc_type_get_columns(type);
        if (base == SPVC_BASETYPE_STRUCT) {
            const spvc_type_id struct_id = spvc_type_get_base_type_id(type);
            const spvc_type struct_type = spvc_compiler_get_type_handle(compiler_, struct_id);
            const std::string name = type_name(struct_id, nullptr);
            size_t declared = 0;
            check(spvc_compiler_get_declared_struct_size(compiler_, struct_type, &declared),
                  "size struct '" + name + "'");
            const uint32_t size = static_cast<uint32_t>(declared);
            const std::string note = "struct " + name + ": " + std::to_string(size) + " bytes, the declared size";
            const StructDef& def = build_struct(struct_id, name, note, size, where + " (struct '" + name + "')");
            return {def.name, name, def.size, def.align, true};
        }
        // The scalars a block may hold (glslang stores a GLSL bool as a uint) and their vectors.
        struct Scalar {
            spvc_basetype base;
            const char *cpp, *glsl, *vector;  // vector: glm's and GLSL's prefix; null: none mirrored
            uint32_t bytes;
        };
        static const Scalar kScalars[] = {
            {SPVC_BASETYPE_FP32, "float", "float", "vec", 4},
            {SPVC_BASETYPE_INT32, "int32_t", "int", "ivec", 4},
            {SPVC_BASETYPE_UINT32, "uint32_t", "uint", "uvec", 4},
            {SPVC_BASETYPE_INT64, "int64_t", "int64_t", nullptr, 8},
            {SPVC_BASETYPE_UINT64, "uint64_t", "uint64_t", nullptr, 8},
            {SPVC_BASETYPE_FP64, "double", "double", nullptr, 8},
        };
        const Scalar* scalar = nullptr;
        for (const Scalar& candidate : kScalars) {
            if (candidate.base == base) scalar = &candidate;
        }
        if (!scalar) fail(where, "a type of SPIR-V base type " + std::to_string(base) + " has no C++ mirror here");
        const uint32_t bytes = scalar->bytes;
        if (columns == 1 && vecsize == 1) return {scalar->cpp, scalar->glsl, bytes, bytes, false};
        if (!scalar->vector) fail(where, "a 64-bit vector or matrix; the generator mirrors 64-bit scalars only");
        if (columns == 1) {
            const std::string n = std::to_string(vecsize);
            return {"glm::" + std::string(scalar->vector) + n, scalar->vector + n, 4 * vecsize, 4, false};
        }
        if (base != SPVC_BASETYPE_FP32) fail(where, "a matrix of integers");
        unsigned matrix_stride = 0;
        check(spvc_compiler_type_struct_member_matrix_stride(compiler_, parent, index, &matrix_stride),
              "read the matrix stride of " + where);
        const std::string shape =
            columns == vecsize ? std::to_string(columns) : std::to_string(columns) + "x" + std::to_string(vecsize);
        if (matrix_stride != 4 * vecsize) {
            fail(where, "mat" + shape + " with a column stride of " + std::to_string(matrix_stride) +
                            " bytes; glm::mat" + shape + "'s columns are " + std::to_string(4 * vecsize) +
                            " (in a std140 block declare it mat" + std::to_string(columns) + "x4, or vec4 columns)");
        }
        return {"glm::mat" + shape, "mat" + shape, 4 * vecsize * columns, 4, false};
    }

    void write_struct(std::ostringstream& out, const StructDef& def) const {
        std::set<std::string> member_names;
        for (const Member& m : def.members) member_names.insert(m.name);
        out << "\n// " << def.note << "\n";
        if (def.shared) {
            out << "// The one C++ type of every shader that declares it (shaders/" << shared_->shader << ").\n";
            out << "using " << def.name << " = ::" << shared_->ns << "::" << def.name << ";\n";
            write_asserts(out, def);
            return;
        }
        out << "struct " << def.name << " {\n";
        std::vector<std::pair<std::string, std::string>> lines;  // declaration, comment
        size_t width = 0;
        for (const Member& m : def.members) {
            std::string type = m.type;
            // A member named like a struct of this header would change that name's meaning in the
            // struct (an error in C++): the type is then named with its namespace.
            if (m.struct_type && member_names.count(m.type)) type = "::" + ns_ + "::" + type;
            std::string declaration = "    " + type + " " + m.name;
            if (m.count) declaration += "[" + std::to_string(m.count) + "]";
            declaration += "{};";
            const std::string comment =
                m.padding ? "padding, " + std::to_string(m.size) + " bytes at " + std::to_string(m.offset)
                          : m.glsl + " at " + std::to_string(m.offset);
            width = std::max(width, declaration.size());
            lines.emplace_back(declaration, comment);
        }
        for (const auto& [declaration, comment] : lines) {
            out << declaration << std::string(width - declaration.size() + 2, ' ') << "// " << comment << "\n";
        }
        out << "};\n";
        write_asserts(out, def);
    }

    static void write_asserts(std::ostringstream& out, const StructDef& def) {
        out << "static_assert(sizeof(" << def.name << ") == " << def.size << ");\n";
        for (const Member& m : def.members) {
            if (m.padding) continue;
            out << "static_assert(offsetof(" << def.name << ", " << m.name << ") == " << m.offset << ");\n";
        }
    }

    spvc_compiler compiler_ = nullptr;
    std::string source_;  // the source under shaders/
    std::string shader_;  // the variant being read, for messages
    std::vector<std::string> variants_;
    std::string ns_;
    const SharedStructs* shared_;
    std::map<std::string, StructDef> structs_;
    std::vector<StructDef> order_;  // definition order: each after the types it uses
};

std::vector<uint32_t> read_words(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) throw GeneratorError("cannot read " + path.string());
    const auto bytes = static_cast<size_t>(in.tellg());
    if (bytes % 4 != 0 || bytes == 0)
        throw GeneratorError(path.string() + " is not SPIR-V (" + std::to_string(bytes) + " bytes)");
    std::vector<uint32_t> words(bytes / 4);
    in.seekg(0);
    in.read(reinterpret_cast<char*>(words.data()), static_cast<std::streamsize>(bytes));
    return words;
}

// "godrays/godray_blur.comp" -> "godray_blur_comp".
std::string namespace_of(const std::string& shader) {
    std::string stem = std::filesystem::path(shader).filename().string();
    for (char& c : stem) {
        const bool word = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
        if (!word) c = '_';
    }
    return "vkw::glsl::" + stem;
}

// Writes `text` to `path` unless it already holds exactly that (the file's time then stays, and
// nothing that includes it is rebuilt).
void write_if_changed(const std::filesystem::path& path, const std::string& text) {
    {
        std::ifstream in(path, std::ios::binary);
        if (in) {
            std::ostringstream old;
            old << in.rdbuf();
            if (old.str() == text) return;
        }
    }
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
    const std::filesystem::path temporary = path.string() + ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out << text;
        if (!out) throw GeneratorError("cannot write " + temporary.string());
    }
    std::filesystem::rename(temporary, path);
}

struct Context {
    spvc_context handle = nullptr;
    std::string last_error;
    Context() {
        if (spvc_context_create(&handle) != SPVC_SUCCESS) throw GeneratorError("SPIRV-Cross: no context");
        spvc_context_set_error_callback(
            handle, [](void* self, const char* error) { static_cast<Context*>(self)->last_error = error; }, this);
    }
    ~Context() { spvc_context_destroy(handle); }
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;
};

// SPV parsed into a SPIRV-Cross compiler owned by `context` (the parsed IR keeps its own copy of
// the words); `label` names it in errors.
spvc_compiler parse_shader(Context& context, const std::string& spv, const std::string& label) {
    const std::vector<uint32_t> words = read_words(spv);
    spvc_parsed_ir ir = nullptr;
    spvc_compiler compiler = nullptr;
    if (spvc_context_parse_spirv(context.handle, words.data(), words.size(), &ir) != SPVC_SUCCESS ||
        spvc_context_create_compiler(context.handle, SPVC_BACKEND_NONE, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP,
                                     &compiler) != SPVC_SUCCESS) {
        throw GeneratorError("shader '" + label + "': SPIRV-Cross could not parse " + spv + " (" + context.last_error +
                             ")");
    }
    return compiler;
}

}  // namespace

// The variant a compiled file holds: "<source file name>.<variant>.spv", or empty for "<source file name>.spv".
std::string variant_of(const std::string& spv, const std::string& shader) {
    const std::string file = std::filesystem::path(spv).filename().string();
    const std::string name = std::filesystem::path(shader).filename().string();
    const bool compiled = file.size() > 4 && file.compare(file.size() - 4, 4, ".spv") == 0;
    const std::string stem = compiled ? file.substr(0, file.size() - 4) : "";
    if (stem == name) return "";
    if (!compiled || stem.rfind(name + ".", 0) != 0 || stem.size() == name.size() + 1) {
        throw GeneratorError(spv + " is no compiled variant of " + shader + " (" + name + "[.<variant>].spv)");
    }
    return stem.substr(name.size() + 1);
}

int main(int argc, char** argv) {
    std::vector<std::string> positional;
    std::string shared_spv, shared_shader;
    for (int i = 1; i < argc; ++i) {
        if (std::string(argv[i]) == "--shared" && i + 2 < argc) {
            shared_spv = argv[++i];
            shared_shader = argv[++i];
        } else {
            positional.push_back(argv[i]);
        }
    }
    if (positional.size() < 3) {
        std::cerr << "usage: " << argv[0] << " OUT SHADER SPV... [--shared SHARED_SPV SHARED_SHADER]\n"
                  << "  writes the C++ mirrors of the push-constant and uniform blocks of SHADER (the source under\n"
                  << "  shaders/, e.g. godrays/godray_blur.comp), compiled as SPV (its variants' files: the union of\n"
                  << "  their blocks), to OUT; structs of SHARED_SHADER's (compiled to SHARED_SPV) are aliased\n";
        return 2;
    }
    const std::string out = positional[0], shader = positional[1];
    try {
        Context context;
        std::optional<SharedStructs> shared;
        if (!shared_spv.empty()) {
            Generator shared_generator(shared_shader, namespace_of(shared_shader));
            shared_generator.run(parse_shader(context, shared_spv, shared_shader), "");
            shared = SharedStructs{shared_shader, namespace_of(shared_shader), shared_generator.structs()};
        }
        Generator generator(shader, namespace_of(shader), shared ? &*shared : nullptr);
        for (size_t i = 2; i < positional.size(); ++i) {
            const std::string variant = variant_of(positional[i], shader);
            const std::string label = shader + (variant.empty() ? "" : " (variant " + variant + ")");
            generator.run(parse_shader(context, positional[i], label), variant);
        }
        write_if_changed(out, generator.header());
    } catch (const std::exception& e) {
        std::cerr << "vkwater_shader_structs: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
