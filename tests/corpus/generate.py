#!/usr/bin/env python3
"""Writes the malformed-input corpus: tests/corpus/cases/ and tests/corpus/cases.tsv.

Each case is an input vkwater must refuse cleanly: exit 1 and one line naming the file, the field
and what is accepted (never a crash, a hang, exit 0 or exit 2). Most are scenes derived from the
built-in ones by one mutation each, run through `vkwater check`; the rest are glTF files, EXR files,
`--set` values and command lines. Run it again after a built-in scene changes:

    python3 tests/corpus/generate.py

cases.tsv has one row per case, tab-separated: id, category, the arguments to vkwater (a shell
word list; {cases} stands for the cases folder), the expected exit code, and a regular expression
(ECMAScript) the single output line must match, in which {cases} stands for the folder too.
tests/corpus/corpus_test.cpp runs every row.
"""
import base64
import copy
import json
import pathlib
import re
import shutil
import struct
import zlib

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent.parent
CASES = HERE / "cases"
SCENES = ["pool", "lake", "ocean", "box", "calm", "underwater"]

rows = []


def add(case_id, category, args, exit_code, pattern):
    assert "\t" not in args and "\t" not in pattern and "\n" not in pattern
    rows.append((case_id, category, args, str(exit_code), pattern))


def slug(path):
    return re.sub(r"[^A-Za-z0-9]+", "_", path).strip("_")


def write(name, data):
    target = CASES / name
    target.parent.mkdir(parents=True, exist_ok=True)
    if isinstance(data, str):
        data = data.encode("utf-8")
    target.write_bytes(data)
    return name


def scene_text(document):
    return json.dumps(document, indent=1) + "\n"


def field_regex(path):
    """The message's start for a field: 'vkwater: <file>: <path>: '."""
    return re.escape(path) + ": "


def leaves(node, path=""):
    """(path, value) of every leaf: numbers, strings, booleans and arrays of numbers."""
    if isinstance(node, dict):
        for key, value in node.items():
            yield from leaves(value, f"{path}.{key}" if path else key)
    elif isinstance(node, list) and node and all(isinstance(v, dict) for v in node):
        for i, value in enumerate(node):
            yield from leaves(value, f"{path}[{i}]")
    else:
        yield path, node


def objects(node, path=""):
    if isinstance(node, dict):
        yield path, node
        for key, value in node.items():
            yield from objects(value, f"{path}.{key}" if path else key)
    elif isinstance(node, list):
        for i, value in enumerate(node):
            yield from objects(value, f"{path}[{i}]")


def set_at(document, path, value):
    """A copy of `document` with the leaf at `path` (dots and [i]) replaced."""
    result = copy.deepcopy(document)
    parts = re.findall(r"[^.\[\]]+|\[\d+\]", path)
    node = result
    for part in parts[:-1]:
        node = node[int(part[1:-1])] if part.startswith("[") else node[part]
    last = parts[-1]
    if last.startswith("["):
        node[int(last[1:-1])] = value
    else:
        node[last] = value
    return result


def load_builtin(name):
    document = json.loads((ROOT / "scenes" / f"{name}.json").read_text())
    return document


# --- Scenes, one mutation each -------------------------------------------------------------------

# A value of the wrong JSON type for each kind of leaf, and what the loader must say about it.
WRONG_TYPE = {
    "number": ("wide", r"expected (a number|an integer|a number or \"infinite\"), got string \"wide\""),
    # A number that may be the word "infinite" instead (water.half_extent).
    "number or word": ("wide", r"expected a number or \"infinite\", got string \"wide\""),
    "string": (42, r"expected (a string|one of .*), got number 42"),
    "bool": ("yes", r"expected (a boolean|true or false), got string \"yes\""),
    "vector": ("up", r"expected an array of \d numbers, got string \"up\""),
}


def kind_of(value):
    if isinstance(value, bool):
        return "bool"
    if isinstance(value, (int, float)):
        return "number"
    if value == "infinite":
        return "number or word"
    if isinstance(value, str):
        return "string"
    if isinstance(value, list) and value and all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in value):
        return "vector"
    return None


def scene_cases():
    for name in SCENES:
        base = load_builtin(name)
        for receiver in base.get("receivers", []):
            if receiver.get("type") == "gltf":
                receiver["file"] = "assets/" + pathlib.Path(receiver["file"]).name
        case = write(f"valid-{name}.json", scene_text(base))
        add(f"valid-{name}", "valid", f"check {{cases}}/{case}", 0, "a valid scene")
        for path, value in leaves(base):
            kind = kind_of(value)
            if kind is None or path == "description":
                continue
            wrong, says = WRONG_TYPE[kind]
            case = write(f"type-{name}-{slug(path)}.json", scene_text(set_at(base, path, wrong)))
            add(f"type-{name}-{slug(path)}", "type", f"check {{cases}}/{case}", 1,
                f"^vkwater: {{cases}}/{re.escape(case)}: {field_regex(path)}{says}")
            if kind == "number":
                # JSON allows 1e999; it is no finite number.
                text = scene_text(set_at(base, path, 12345.678)).replace("12345.678", "1e999", 1)
                case = write(f"infinite-{name}-{slug(path)}.json", text)
                add(f"infinite-{name}-{slug(path)}", "number", f"check {{cases}}/{case}", 1,
                    f"^vkwater: {{cases}}/{re.escape(case)}: {field_regex(path)}1e999 is not a finite number")
            if kind == "vector":
                case = write(f"short-{name}-{slug(path)}.json", scene_text(set_at(base, path, value[:-1])))
                add(f"short-{name}-{slug(path)}", "vector", f"check {{cases}}/{case}", 1,
                    f"^vkwater: {{cases}}/{re.escape(case)}: {field_regex(path)}expected an array of {len(value)} numbers")
        for path, node in objects(base):
            mutated = copy.deepcopy(base)
            target = mutated
            for part in re.findall(r"[^.\[\]]+|\[\d+\]", path):
                target = target[int(part[1:-1])] if part.startswith("[") else target[part]
            target["bogus_field"] = 1
            where = f"{path}.bogus_field" if path else "bogus_field"
            case = write(f"unknown-{name}-{slug(path) or 'top'}.json", scene_text(mutated))
            add(f"unknown-{name}-{slug(path) or 'top'}", "unknown", f"check {{cases}}/{case}", 1,
                f"^vkwater: {{cases}}/{re.escape(case)}: {re.escape(where)}: unknown field")
        text = scene_text(base).encode()
        for share in (1, 25, 50, 75, 99):
            cut = len(text) * share // 100
            case = write(f"truncated-{name}-{share}.json", text[:cut])
            add(f"truncated-{name}-{share}", "syntax", f"check {{cases}}/{case}", 1,
                f"^vkwater: {{cases}}/{re.escape(case)}: .*(malformed JSON|empty)")


def encoding_cases():
    base = scene_text(load_builtin("pool"))
    utf16 = b"\xff\xfe" + base.encode("utf-16-le")
    cases = {
        "utf16": utf16,
        "utf16-big-endian": b"\xfe\xff" + base.encode("utf-16-be"),
        "invalid-utf8": base.replace('"description": "', '"description": "\xff', 1).encode("latin-1"),
        "nul-byte": base.encode().replace(b"{", b"{\x00", 1),
        "binary": bytes(range(256)) * 4,
        "empty": b"",
        "only-bom": b"\xef\xbb\xbf",
    }
    # RFC 8259 lets a parser ignore a UTF-8 byte order mark, and vkwater does.
    case = write("encoding-utf8-bom.json", b"\xef\xbb\xbf" + base.encode())
    add("encoding-utf8-bom", "valid", f"check {{cases}}/{case}", 0, "a valid scene")
    for label, data in cases.items():
        case = write(f"encoding-{label}.json", data)
        add(f"encoding-{label}", "encoding", f"check {{cases}}/{case}", 1, f"^vkwater: {{cases}}/{re.escape(case)}: ")


def nesting_cases():
    base = load_builtin("calm")
    for depth in (65, 1000, 100000):
        text = scene_text(base).replace('"description": ', '"description": ' + "[" * depth + "]" * depth + ", \"x\": ", 1)
        case = write(f"nesting-description-{depth}.json", text)
        add(f"nesting-description-{depth}", "nesting", f"check {{cases}}/{case}", 1,
            f"^vkwater: {{cases}}/{re.escape(case)}: .*nested too deeply \\(accepted: at most 64 levels")
    # 50000 levels in one --set value (an argument is at most 128 KiB), made by the shell.
    case = write("nesting-set.json", scene_text(base))
    add("set-nesting-50000", "set",
        f"check {{cases}}/{case} --set \"description=$(printf '%50000s' '' | tr ' ' '[')\"", 1,
        r"nested too deeply")


# --- --set and the command line -----------------------------------------------------------------

def set_cases():
    pool = "{cases}/set-pool.json"
    write("set-pool.json", scene_text(load_builtin("pool")))
    field = r"^vkwater: {cases}/set-pool\.json: "
    cases = [
        ("wrong-type", "camera.fov_y_deg=wide", field + r"camera\.fov_y_deg: expected a number"),
        ("out-of-range", "camera.fov_y_deg=0", field + r"camera\.fov_y_deg: 0 is out of range"),
        ("unknown-key", "camera.fovy=60", field + r"camera\.fovy: unknown field \(did you mean 'fov_y_deg'\?\)"),
        ("unknown-section", "camra.fov_y_deg=60", field + r"camra: unknown field"),
        ("no-equals", "camera.fov_y_deg", r"camera\.fov_y_deg"),
        ("empty-key", "=60", r"=60"),
        ("empty-segment", "camera..fov_y_deg=60", r"camera\.\.fov_y_deg"),
        ("index-past-end", "receivers[3].albedo=[1,1,1]", r"receivers\[3\]"),
        ("index-not-number", "receivers[x]=1", r"receivers\[x\]"),
        ("into-number", "camera.fov_y_deg.x=1", r"camera\.fov_y_deg"),
        ("infinite", "camera.fov_y_deg=1e999", r"camera\.fov_y_deg"),
        ("nan-text", "sun.elevation_deg=nan", r"sun\.elevation_deg"),
        ("vector-short", "sun.irradiance=[1,2]", r"sun\.irradiance: expected an array of 3 numbers"),
        ("remove-required", "sky=null", r"sky: missing required field"),
        ("long-value", "description=" + "x" * 1, None),
        ("huge-string-key", "camera." + "k" * 5000 + "=1", r"\(5\d{3} characters\)"),
        ("not-utf8", "\"$(printf 'camera.fov_y_deg=\\377\\376')\"", field + r"camera\.fov_y_deg: expected a number"),
        # Found by the --set fuzzer: a choice's "unknown value" message printed the value with a
        # JSON printer that throws on bytes that are not UTF-8 (an internal error, exit 2).
        ("not-utf8-choice", "\"$(printf 'effects.godrays.mode=off\\351\\351')\"",
         field + r"effects\.godrays\.mode: unknown value"),
        ("unclosed-array", "sun.irradiance=[1,2", r"sun\.irradiance"),
    ]
    for label, value, pattern in cases:
        if pattern is None:
            continue
        argument = value if value.startswith('"') else "'" + value + "'"
        add(f"set-{label}", "set", f"check {pool} --set {argument}", 1, pattern)


def cli_cases():
    pool = "{cases}/set-pool.json"
    cases = [
        ("no-command", "", r"^vkwater: .*subcommand"),
        ("unknown-command", "paint " + pool, r"^vkwater: "),
        ("unknown-flag", f"check {pool} --bogus", r"^vkwater: .*--bogus"),
        ("missing-scene", "check", r"^vkwater: .*scene"),
        ("scene-absent", "check {cases}/absent.json", r"^vkwater: cannot open scene file '{cases}/absent\.json': No such file"),
        ("scene-folder", "check {cases}", r"^vkwater: cannot open scene file '{cases}'"),
        ("passes-width-zero", f"passes {pool} --width 0", r"--width"),
        ("passes-height-huge", f"passes {pool} --height 99999", r"--height"),
        ("passes-width-text", f"passes {pool} --width wide", r"--width"),
        ("render-spp-not-square", f"render {pool} --spp 3 --width 8 --height 6 --out /nonexistent/never.exr", r"--spp"),
        ("render-unknown-extension", f"render {pool} --out /nonexistent/x.tiff", r"x\.tiff"),
        ("render-out-folder-absent", f"render {pool} --out {{cases}}/absent/x.exr", r"absent/x\.exr"),
        ("reference-threads-negative", f"reference {pool} --threads -1 --out /nonexistent/never.exr", r"--threads"),
        ("reference-cells-nan", f"reference {pool} --cells-per-wavelength nan --out /nonexistent/never.exr", r"nan"),
        ("compare-one-file", "compare {cases}/exr-valid.exr", r"^vkwater: "),
        ("compare-downsample-zero", "compare {cases}/exr-valid.exr {cases}/exr-valid.exr --downsample 0", r"--downsample"),
        ("help-unknown", "help paint", r"no command 'paint'"),
        ("view-frames-negative", f"view {pool} --frames -1", r"--frames"),
        ("bench-out-dir-file",
         f"bench {pool} --reference {{cases}}/exr-valid.exr --out-dir {{cases}}/set-pool.json --sweep water.grid_resolution=4",
         r"set-pool\.json"),
    ]
    for label, args, pattern in cases:
        add(f"cli-{label}", "cli", args, 1, pattern)


# --- glTF ----------------------------------------------------------------------------------------

def gltf_cases():
    rock = json.loads((ROOT / "scenes/assets/rock.gltf").read_text())
    write("assets/rock.gltf", (ROOT / "scenes/assets/rock.gltf").read_bytes())
    scene = load_builtin("calm")

    def add_gltf(label, data, pattern, extension="gltf"):
        name = write(f"gltf/{label}.{extension}", data)
        document = copy.deepcopy(scene)
        document["receivers"] = [{"type": "gltf", "file": pathlib.Path(name).name}]
        case = write(f"gltf/scene-{label}.json", scene_text(document))
        add(f"gltf-{label}", "gltf", f"check {{cases}}/{case}", 1,
            f"^vkwater: {{cases}}/{re.escape(case)}: receivers\\[0\\]\\.file: .*{pattern}")

    def mutated(change):
        document = copy.deepcopy(rock)
        change(document)
        return json.dumps(document)

    text = json.dumps(rock)
    for share in (10, 50, 90):
        add_gltf(f"truncated-{share}", text[: len(text) * share // 100], "malformed glTF")
    add_gltf("not-json", "hello", "malformed glTF")
    add_gltf("empty", "", "")
    add_gltf("nested", '{"asset": {"version": "2.0"}, "extras": ' + "[" * 100000 + "]" * 100000 + "}",
             r"nested 100001 levels deep \(accepted: at most 64\)")
    add_gltf("nul-byte", text.replace("{", "{\x00", 1), "a NUL byte at byte 1")
    add_gltf("required-draco", mutated(lambda d: d.update(extensionsRequired=["KHR_draco_mesh_compression"])),
             "needs the glTF extension 'KHR_draco_mesh_compression'")
    add_gltf("buffer-mime", mutated(lambda d: d["buffers"][0].update(
        uri="data:image/png;base64," + d["buffers"][0]["uri"].split(",", 1)[1])), r"buffers\[0\]\.uri: a data URI")
    add_gltf("buffer-base64", mutated(lambda d: d["buffers"][0].update(uri=d["buffers"][0]["uri"][:-1])),
             "base64 is malformed")
    add_gltf("buffer-outside", mutated(lambda d: d["buffers"][0].update(uri="../../../../etc/passwd")),
             r"buffers\[0\]\.uri '\.\./\.\./\.\./\.\./etc/passwd' resolves outside the scene's folder")
    add_gltf("buffer-absolute", mutated(lambda d: d["buffers"][0].update(uri="/etc/passwd")),
             "resolves outside the scene's folder")
    add_gltf("buffer-escaped", mutated(lambda d: d["buffers"][0].update(uri="%2e%2e/%2e%2e/%2e%2e/etc/passwd")),
             "resolves outside the scene's folder")
    add_gltf("buffer-escape-broken", mutated(lambda d: d["buffers"][0].update(uri="%2e%%%2Ee2/rock.bin")),
             r"buffers\[0\]\.uri: the '%' at character 4 does not start a %XX escape")
    add_gltf("buffer-folder", mutated(lambda d: d["buffers"][0].update(uri=".")), r"buffers\[0\]\.uri '\.' names a folder")
    add_gltf("buffer-missing", mutated(lambda d: d["buffers"][0].update(uri="absent.bin")), "")
    add_gltf("image-outside", mutated(lambda d: d.update(images=[{"uri": "../../../secret.png"}])),
             r"images\[0\]\.uri")
    add_gltf("accessor-count-wraps", mutated(lambda d: d["accessors"][0].update(count=2**61 + 1)), "")
    add_gltf("accessor-count-huge", mutated(lambda d: d["accessors"][0].update(count=10**9)), "")
    add_gltf("view-offset-wraps", mutated(lambda d: d["bufferViews"][0].update(byteOffset=2**64 - 16)), "")
    add_gltf("view-length-past-buffer", mutated(lambda d: d["bufferViews"][0].update(byteLength=10**9)), "")
    add_gltf("accessor-view-absent", mutated(lambda d: d["accessors"][0].update(bufferView=99)), "")
    add_gltf("mode-points", mutated(lambda d: d["meshes"][0]["primitives"][0].update(mode=0)), "POINTS")
    add_gltf("mode-lines", mutated(lambda d: d["meshes"][0]["primitives"][0].update(mode=1)), "LINES")
    add_gltf("node-cycle", mutated(lambda d: d["nodes"][0].update(children=[0])), "")
    add_gltf("node-absent", mutated(lambda d: d["scenes"][0].update(nodes=[99])), "no node 99")
    add_gltf("scene-absent", mutated(lambda d: d.update(scene=7)), "")
    add_gltf("mesh-absent", mutated(lambda d: d["nodes"][0].update(mesh=99)), "")
    add_gltf("no-triangles", mutated(lambda d: d.update(scenes=[{"nodes": []}])), "contains no triangles")
    add_gltf("material-colour", mutated(lambda d: d.setdefault("materials", [{}])[0].update(
        pbrMetallicRoughness={"baseColorFactor": [2, 0, 0, 1]})), "")
    add_gltf("node-scale-huge", mutated(lambda d: d["nodes"][0].update(scale=[1e300, 1e300, 1e300])), "")
    add_gltf("asset-missing", mutated(lambda d: d.pop("asset")), "")
    # Base colour textures (a square with an embedded PNG): images stb_image cannot read, beyond
    # the limits, and textures, samplers and wrap modes that do not exist.
    square = json.loads((ROOT / "tests/fuzz/seeds/gltf/textured_square.gltf").read_text())

    def textured(change):
        document = copy.deepcopy(square)
        change(document)
        return json.dumps(document)

    def png(width, height):
        rows = b"".join(b"\x00" + bytes(4 * width) for _ in range(height))
        chunk = lambda kind, data: (struct.pack(">I", len(data)) + kind + data +
                                    struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))
        return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))

    image_uri = lambda data: "data:image/png;base64," + base64.b64encode(data).decode()
    add_gltf("image-not-an-image", textured(lambda d: d["images"][0].update(uri=image_uri(b"not an image"))),
             r"images\[0\]: not an image stb_image decodes")
    add_gltf("image-truncated", textured(lambda d: d["images"][0].update(uri=image_uri(png(4, 4)[:40]))),
             r"images\[0\]: ")
    add_gltf("image-too-wide", textured(lambda d: d["images"][0].update(uri=image_uri(png(8193, 1)))),
             r"images\[0\]: 8193 x 1 texels \(accepted: 1 to 8192 per side\)")
    add_gltf("texture-absent", textured(lambda d: d["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"].update(
        index=9)), r"no textures\[9\]")
    add_gltf("texture-image-absent", textured(lambda d: d["textures"][0].update(source=7)),
             r"textures\[0\] has no image")
    add_gltf("sampler-absent", textured(lambda d: d["textures"][0].update(sampler=5)), r"no samplers\[5\]")
    add_gltf("sampler-wrap", textured(lambda d: d["samplers"][0].update(wrapS=1234)),
             r"samplers\[0\]\.wrapS 1234 is not a glTF wrap mode")
    add_gltf("texture-transform-overflows", textured(lambda d: d["materials"][0]["pbrMetallicRoughness"][
        "baseColorTexture"]["extensions"]["KHR_texture_transform"].update(scale=[1e300, 1])),
             r"TEXCOORD_0 of vertex 2 is not finite")
    add_gltf("colour-count-differs", textured(lambda d: d["accessors"][4].update(normalized=False, componentType=5126,
                                                                              count=1)), r"COLOR_0 and POSITION counts differ")
    # .glb: a 12-byte header, then a JSON chunk.
    body = text.encode()
    body += b" " * (-len(body) % 4)
    chunk = struct.pack("<II", len(body), 0x4E4F534A) + body
    glb = lambda version, length=None: struct.pack("<4sII", b"glTF", version, length or 12 + len(chunk)) + chunk
    add_gltf("glb-version-1", glb(1), "version", "glb")
    add_gltf("glb-version-99", glb(99), "version", "glb")
    add_gltf("glb-length-past-file", glb(2, 10**6), "", "glb")
    add_gltf("glb-truncated", glb(2)[:40], "", "glb")
    add_gltf("glb-header-only", b"glTF", "", "glb")
    # The file named by the scene.
    document = copy.deepcopy(scene)
    document["receivers"] = [{"type": "gltf", "file": "../../../../etc/passwd"}]
    case = write("gltf/scene-file-outside.json", scene_text(document))
    add("gltf-file-outside", "gltf", f"check {{cases}}/{case}", 1, r"receivers\[0\]\.file: the glTF file '.*' resolves outside")
    document["receivers"] = [{"type": "gltf", "file": "."}]
    case = write("gltf/scene-file-folder.json", scene_text(document))
    add("gltf-file-folder", "gltf", f"check {{cases}}/{case}", 1, r"receivers\[0\]\.file: ")


# --- EXR -----------------------------------------------------------------------------------------

def small_exr(width=8, height=6, short_line=None):
    """An uncompressed scanline OpenEXR of float B, G, R, written by hand (the format's layout:
    magic, version, header attributes, the line offset table, then one chunk per line). With
    short_line=y, that line's chunk declares and holds 8 bytes instead of its 3 * width floats."""
    def attribute(name, kind, value):
        return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(value)) + value

    channels = b"".join(c.encode() + b"\0" + struct.pack("<iB3xii", 2, 0, 1, 1) for c in "BGR") + b"\0"
    window = struct.pack("<iiii", 0, 0, width - 1, height - 1)
    header = (b"\x76\x2f\x31\x01" + struct.pack("<i", 2) + attribute("channels", "chlist", channels) +
              attribute("compression", "compression", b"\0") + attribute("dataWindow", "box2i", window) +
              attribute("displayWindow", "box2i", window) + attribute("lineOrder", "lineOrder", b"\0") +
              attribute("pixelAspectRatio", "float", struct.pack("<f", 1)) +
              attribute("screenWindowCenter", "v2f", struct.pack("<ff", 0, 0)) +
              attribute("screenWindowWidth", "float", struct.pack("<f", 1)) + b"\0")
    lines = []
    for y in range(height):
        pixels = b"".join(struct.pack(f"<{width}f", *[(c + 1) * 0.25 + 0.01 * (x + y) for x in range(width)])
                          for c in range(3))
        if y == short_line:
            pixels = pixels[:8]
        lines.append(struct.pack("<ii", y, len(pixels)) + pixels)
    offset = len(header) + 8 * height
    table = b""
    for line in lines:
        table += struct.pack("<Q", offset)
        offset += len(line)
    return header + table + b"".join(lines)


def exr_cases():
    valid = small_exr()
    write("exr-valid.exr", valid)
    add("exr-valid", "valid", "compare {cases}/exr-valid.exr {cases}/exr-valid.exr", 0, "")

    def add_exr(label, data, pattern):
        name = write(f"exr/{label}.exr", data)
        add(f"exr-{label}", "exr", f"compare {{cases}}/{name} {{cases}}/exr-valid.exr", 1,
            f"^vkwater: cannot read '{{cases}}/{re.escape(name)}': {pattern}")

    for share in (1, 5, 10, 30, 50, 70, 90, 99):
        add_exr(f"truncated-{share}", valid[: len(valid) * share // 100], "")
    add_exr("empty", b"", "")
    add_exr("not-exr", b"P6 1 1 255\n\0\0\0", "not an OpenEXR file")
    add_exr("magic-only", valid[:4], "")
    i = valid.find(b"dataWindow\0box2i\0") + 17 + 4
    for label, window in {"window-huge": (0, 0, 19999, 19999), "window-inverted": (10, 10, 0, 0),
                          "window-extreme": (-2**31, -2**31, 2**31 - 1, 2**31 - 1)}.items():
        add_exr(label, valid[:i] + struct.pack("<iiii", *window) + valid[i + 16:], "")
    # A header attribute that declares far more bytes than the file holds: refused before OpenEXR
    # allocates them (engine/image/exr_header_scan.hpp).
    j = valid.find(b"screenWindowWidth\0float\0") + len(b"screenWindowWidth\0float\0")
    add_exr("attribute-huge", valid[:j] + struct.pack("<i", 2000000000) + valid[j + 4:],
            r"a corrupt OpenEXR file \(attribute 'screenWindowWidth' \(at byte \d+\) declares 2000000000 bytes")
    # An uncompressed chunk shorter than its line, every offset consistent: OpenEXR's reader would
    # take the rest of the line from whatever follows the chunk, and its checker lets it pass.
    add_exr("chunk-short", small_exr(short_line=2),
            r"a corrupt OpenEXR file \(the chunk of line 2 \(at byte \d+\) holds 8 bytes, and an uncompressed "
            r"line of this image takes 96\)")
    flipped = bytearray(valid)
    for k in range(len(flipped) // 2, len(flipped), 97):
        flipped[k] ^= 0x5A
    add_exr("corrupt-data", bytes(flipped), "")


def main():
    if CASES.exists():
        shutil.rmtree(CASES)
    CASES.mkdir(parents=True)
    scene_cases()
    encoding_cases()
    nesting_cases()
    set_cases()
    cli_cases()
    gltf_cases()
    exr_cases()
    with open(HERE / "cases.tsv", "w") as table:
        table.write("# id\tcategory\targuments\texit\tpattern (generated by tests/corpus/generate.py)\n")
        for row in rows:
            table.write("\t".join(row) + "\n")
    print(f"{len(rows)} cases in {CASES.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
