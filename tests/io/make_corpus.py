#!/usr/bin/env python3
"""Writes the seed corpora of the text parsers' fuzz targets (tests/io/corpus/<parser>/): the
shipped files, small valid ones, and the hostile cases the readers must refuse cleanly. Run from
the repository root; the output is committed."""
import glob, json, os, shutil, struct

root = os.path.dirname(os.path.abspath(__file__))
out = os.path.join(root, "corpus")

def put(parser, name, data):
    os.makedirs(os.path.join(out, parser), exist_ok=True)
    with open(os.path.join(out, parser, name), "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())

repo = os.path.dirname(os.path.dirname(root))
# Presets: the shipped ones, then hostile edits of the default.
for p in sorted(glob.glob(repo + "/resources/presets/**/*.json", recursive=True)):
    put("preset", "shipped-" + os.path.basename(p), open(p, "rb").read())
default = open(repo + "/resources/presets/default.json").read()
put("preset", "overflow-1e400.json", default.replace('"damping_ratio": 1.0', '"damping_ratio": 1e400'))
put("preset", "overflow-in-list.json", default.replace("[0.6, 0.35, 0.15]", "[0.6, -1e999, 0.15]"))
put("preset", "duplicate-key.json", default.replace('"damping_ratio": 1.0', '"damping_ratio": 1.0, "damping_ratio": 2.0'))
put("preset", "duplicate-top-key.json", default.replace('"name": "default",', '"name": "a", "name": "b",'))
put("preset", "deep-nesting.json", "[" * 200 + "]" * 200)
put("preset", "empty.json", "")
put("preset", "nul-bytes.json", default[:100] + "\0\0\0" + default[100:])
put("preset", "long-description.json", default.replace('"description": "', '"description": "' + "x" * 20000))
put("preset", "not-an-object.json", "[1, 2, 3]")
put("preset", "truncated.json", default[: len(default) // 2])
put("preset", "wrong-types.json", default.replace('"ring_count": 2', '"ring_count": "two"'))
put("preset", "huge-ring-count.json", default.replace('"ring_count": 2', '"ring_count": 4294967296'))

# Exercises: the shipped ones, then hostile edits.
for p in sorted(glob.glob(repo + "/resources/exercises/*.json")):
    put("exercise", "shipped-" + os.path.basename(p), open(p, "rb").read())
press = json.load(open(repo + "/resources/exercises/press_targets.json"))
trace = json.load(open(repo + "/resources/exercises/trace.json"))
text = json.dumps(press, indent=2)
put("exercise", "overflow-time.json", text.replace('"time_limit_s": ', '"time_limit_s": 1e400, "x": '))
put("exercise", "duplicate-key.json", text.replace('"name": ', '"name": "twice", "name": ', 1))
many = dict(press)
many["press_targets"] = dict(press["press_targets"])
many["press_targets"]["targets"] = [{"point_mm": [1.0 * i, 2.0, 3.0]} for i in range(1001)]
put("exercise", "1001-targets.json", json.dumps(many))
long_trace = dict(trace)
long_trace["trace"] = dict(trace["trace"])
long_trace["trace"]["path"] = [{"vertex": i} for i in range(200)]
put("exercise", "long-trace.json", json.dumps(long_trace))
put("exercise", "vertex-huge.json", text.replace('"vertex": ', '"vertex": 99999999999999999999, "y": ', 1))
put("exercise", "point-nan-like.json", text.replace('"point_mm": [', '"point_mm": [1e308, 1e308, ', 1))
lumps = json.load(open(repo + "/resources/exercises/detect_lumps.json"))
many_lumps = dict(lumps)
many_lumps["detect_lumps"] = dict(lumps["detect_lumps"])
many_lumps["detect_lumps"]["lumps"] = [{"point_mm": [50.0, 0.1 * i, 0.0], "radius_mm": 1.0, "depth_mm": 1.0,
                                        "contrast": 2.0} for i in range(101)]
put("exercise", "101-lumps.json", json.dumps(many_lumps))
stair = dict(lumps)
stair["detect_lumps"] = dict(lumps["detect_lumps"])
stair["detect_lumps"]["staircase"] = {"parameter": "contrast", "start": 4.0, "step": 0.5, "easiest": 6.0,
                                      "hardest": 1.2, "down": 2, "up": 1}
put("exercise", "staircase.json", json.dumps(stair))
stair["detect_lumps"]["staircase"] = {"parameter": "depth_mm", "start": 1e308, "step": -1, "easiest": 1e400,
                                      "hardest": 0, "down": 2.5, "up": 1e20}
put("exercise", "staircase-bad.json", json.dumps(stair).replace("Infinity", "1e400"))
put("exercise", "empty.json", "")
put("exercise", "deep-nesting.json", '{"rubric": ' + "{" * 100 + "}" * 100 + "}")
put("exercise", "wrong-type.json", text.replace('"press_targets"', '"trace"', 1))
put("exercise", "truncated.json", text[: len(text) // 2])
put("exercise", "rubric.json", text.replace('"time_limit_s"', '"rubric": {"peak_force_n": {"weight": 2}}, "time_limit_s"'))

# Waypoint files: the shipped ones, then hostile ones.
for p in sorted(glob.glob(repo + "/resources/exercises/*.path")):
    put("waypoint", "shipped-" + os.path.basename(p), open(p, "rb").read())
put("waypoint", "simple.txt", "0 0 0 0\n1 10 0 0\n2 10 10 0\n")
put("waypoint", "commas-crlf.txt", "0,0,0,0\r\n1,1,1,1\r\n")
put("waypoint", "overflow.txt", "0 0 0 0\n1 1e400 0 0\n")
put("waypoint", "nan-inf.txt", "0 nan 0 0\n1 inf 0 0\n")
put("waypoint", "time-backwards.txt", "0 0 0 0\n2 0 0 0\n1 0 0 0\n")
put("waypoint", "empty.txt", "")
put("waypoint", "comments-only.txt", "# nothing\n# here\n")
put("waypoint", "binary.txt", bytes(range(256)))
put("waypoint", "long-line.txt", "0 " + "1" * 5000 + " 0 0\n")
put("waypoint", "too-few-columns.txt", "0 1 2\n")
put("waypoint", "plus-signs.txt", "+0 +1 -2 +3\n+1 +-1 0 0\n")

# Meshes: the first byte picks the extension (0 off, 1 obj, 2 stl, 3 ply, 4 om, 5 none).
OFF, OBJ, STL, PLY, OM = b"\0", b"\1", b"\2", b"\3", b"\4"
tet_v = [(0, 0, 0), (10, 0, 0), (0, 10, 0), (0, 0, 10)]
tet_f = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
off = "OFF\n4 4 6\n" + "".join("%g %g %g\n" % v for v in tet_v) + "".join("3 %d %d %d\n" % f for f in tet_f)
obj = "".join("v %g %g %g\n" % v for v in tet_v) + "".join("f %d %d %d\n" % (a + 1, b + 1, c + 1) for a, b, c in tet_f)
stl = b"\0" * 80 + struct.pack("<I", 4) + b"".join(
    struct.pack("<12fH", 0, 0, 0, *tet_v[a], *tet_v[b], *tet_v[c], 0) for a, b, c in tet_f)
ply = ("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
       "element face 4\nproperty list uchar int vertex_indices\nend_header\n" +
       "".join("%g %g %g\n" % v for v in tet_v) + "".join("3 %d %d %d\n" % f for f in tet_f))
put("mesh", "tet.off", OFF + off.encode())
put("mesh", "tet.obj", OBJ + obj.encode())
put("mesh", "tet.stl", STL + stl)
put("mesh", "tet.ply", PLY + ply.encode())
put("mesh", "tet-ascii.stl", STL + b"solid t\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n")
put("mesh", "off-1e308.off", OFF + off.replace("10 0 0", "1e308 0 0").encode())
put("mesh", "off-huge-counts.off", OFF + b"OFF\n4000000000 4000000000 0\n0 0 0\n")
put("mesh", "off-negative.off", OFF + b"OFF\n-1 -1 0\n")
put("mesh", "off-truncated.off", OFF + off[: len(off) // 2].encode())
put("mesh", "obj-nan.obj", OBJ + obj.replace("v 10 0 0", "v nan 0 0").encode())
put("mesh", "stl-huge-count.stl", STL + b"\0" * 80 + struct.pack("<I", 0xFFFFFFFF))
put("mesh", "ply-huge-counts.ply", PLY + ply.replace("vertex 4", "vertex 99999999999").encode())
put("mesh", "ply-binary.ply", PLY + b"ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nelement face 1\nend_header\n" + b"\0" * 8)
put("mesh", "nul-in-text.off", OFF + b"OFF\n4 4 6\n\0\0\0")
put("mesh", "om-anything.om", OM + b"OM\0\0garbage")
put("mesh", "no-extension", b"\5" + off.encode())
# What the polygon-soup reader tolerates (docs/meshes.md, "Reading"), and polygons to triangulate.
put("mesh", "obj-crlf-nul.obj", OBJ + obj.replace("\n", "\r\n").encode() + b"\0\0")
put("mesh", "obj-corners.obj", OBJ + ("\ufeff# other tool\nmtllib a.mtl\no organ\n" + "".join("v\t%g %g %g\r" % v for v in tet_v) +
    "vt 0 0\nvn 0 0 1\ng part\nusemtl m\ns 1\nf 1/1/1 3/1/1 2/1/1\nf 1//1 2//1 4//1\nf -4 -1 -2 # relative\nf 2/1 3/1 4/1\nl 1 2\np 3\n").encode())
cube_v = [(x * 10, y * 10, z * 10) for z in (0, 1) for y in (0, 1) for x in (0, 1)]
cube_f = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
put("mesh", "obj-quads.obj", OBJ + ("".join("v %g %g %g\n" % v for v in cube_v) +
    "".join("f %d %d %d %d\n" % tuple(i + 1 for i in f) for f in cube_f)).encode())
put("mesh", "obj-concave.obj", OBJ + b"v 0 0 0\nv 4 0 0\nv 4 4 0\nv 2 1 0\nv 0 4 0\nf 1 2 3 4 5\n")
put("mesh", "off-quads.off", OFF + ("OFF\n8 6 12\n" + "".join("%g %g %g\n" % v for v in cube_v) +
    "".join("4 %d %d %d %d\n" % f for f in cube_f)).encode())
put("mesh", "ply-binary-tet.ply", PLY + b"ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\n"
    b"property float y\nproperty float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n" +
    b"".join(struct.pack("<3f", *v) for v in tet_v) + b"".join(struct.pack("<B3i", 3, *f) for f in tet_f))
# A tetrahedron as OpenMesh 9 writes it (write_mesh of a TriMesh), so the fuzzer starts from a real .om.
put("mesh", "tet.om", OM + bytes.fromhex("4f4d54420400000004000000060000000016000000000000000000000000000020410000000000000000000000000000204100000000000000000000000000002041f8160202000900020401000b02030000000601010803010301030500010a0302010202070303e00609030b07e806040801071c00"))
# What fuzz_polygon_soup found in CGAL's and OpenMesh's readers, refused by the probe first.
put("mesh", "om-bad-dimension.om", OM + open(os.path.join(root, "corpus", "mesh", "tet.om"), "rb").read()[1:17] + b"\x00\x06" + b"\0" * 20)
put("mesh", "ply-property-first.ply", PLY + b"ply\nformat ascii 1.0\nproperty float x\nelement vertex 1\nend_header\n0\n")
put("mesh", "ply-element-twice.ply", PLY + ply.replace("element vertex 4\n", "element vertex 4999999999\nelement vertex 4\n", 1).encode())
put("mesh", "ply-uchar-x.ply", PLY + ply.replace("property float x", "property uchar x").encode())
put("mesh", "ply-int-list-count.ply", PLY + ply.replace("list uchar int", "list int int").encode())
put("mesh", "ply-end-header-glued.ply", PLY + ply.replace("end_header\n", "end_header\xd50 0\nelement x 9\nend_header\n").encode("latin-1"))
put("mesh", "off-glued-count.off", OFF + b"OFF\x02400000300 0\n0 0 2\n")
put("mesh", "off-stoff-short.off", OFF + b"STOFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n")
put("mesh", "stl-ascii-crlf.stl", STL + b"solid t\r\nfacet normal 0 0 0\r\nouter loop\r\nvertex 0 0 0\r\nvertex 1 0 0\r\n"
    b"vertex 0 1 0\r\nendloop\r\nendfacet\r\nendsolid t\r\n")

# Exercise bundles: a small valid one (a tetrahedron, a preset, a path), then hostile edits.
import base64
def b64(s): return base64.b64encode(s.encode() if isinstance(s, str) else s).decode()
tet = "OFF\n4 4 0\n0 0 0\n10 0 0\n0 10 0\n0 0 10\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
small = dict(press)
small["mesh"] = "tet.off"
small["tissue_preset"] = "liver.json"
small["press_targets"] = {"targets": [{"vertex": 3}]}
bundle = {"format": "palpate-exercise-bundle", "version": 1, "exercise_file": "tet.json", "exercise": small,
          "files": [{"name": "tet.off", "role": "mesh", "base64": b64(tet)},
                    {"name": "liver.json", "role": "preset",
                     "base64": b64(open(repo + "/resources/presets/tissues/liver.json", "rb").read())},
                    {"name": "tet.good.path", "role": "path", "base64": b64("0 0 0 20\n1 0 0 9\n")}]}
def bundle_with(change):
    b = json.loads(json.dumps(bundle))
    change(b)
    return json.dumps(b, indent=1)
put("bundle", "valid.palpex", json.dumps(bundle, indent=1))
put("bundle", "no-preset.palpex", bundle_with(lambda b: (b["exercise"].pop("tissue_preset"), b["files"].pop(1))))
put("bundle", "escape-name.palpex", bundle_with(lambda b: b["files"][0].update(name="../tet.off")))
put("bundle", "bad-base64.palpex", bundle_with(lambda b: b["files"][0].update(base64="QQ=A")))
put("bundle", "pad-bits.palpex", bundle_with(lambda b: b["files"][0].update(base64="TR==")))
put("bundle", "two-meshes.palpex", bundle_with(lambda b: b["files"].append(dict(b["files"][0], name="b.off"))))
put("bundle", "same-name.palpex", bundle_with(lambda b: b["files"][2].update(name="tet.off")))
put("bundle", "role-unknown.palpex", bundle_with(lambda b: b["files"][2].update(role="script")))
put("bundle", "files-not-list.palpex", bundle_with(lambda b: b.update(files={"a": 1})))
put("bundle", "version-2.palpex", bundle_with(lambda b: b.update(version=2)))
put("bundle", "mesh-mismatch.palpex", bundle_with(lambda b: b["exercise"].update(mesh="other.off")))
put("bundle", "exercise-broken.palpex", bundle_with(lambda b: b["exercise"].update(time_limit_s=-1)))
put("bundle", "many-files.palpex", bundle_with(lambda b: b["files"].extend(
    [dict(b["files"][2], name="p%d.path" % i) for i in range(70)])))
put("bundle", "empty.palpex", "")

# JSON: anything the reader may meet.
for name, text in [("object.json", '{"a": 1, "b": [1, 2, {"c": null}]}'), ("overflow.json", '{"a": {"b": [0, 1e400]}}'),
                   ("duplicate.json", '{"a": {"k": 1, "k": 2}}'), ("deep.json", "[" * 100 + "]" * 100),
                   ("too-deep.json", "[" * 70 + "]" * 70), ("strings.json", '{"s": "\\u00e9\\ud83d\\ude00\\n"}'),
                   ("numbers.json", "[0, -0, 1e-400, 1.7976931348623157e308, 18446744073709551615, -9223372036854775808]"),
                   ("bad-utf8.json", b'{"s": "\xff\xfe"}'), ("trailing.json", '{"a": 1} x'), ("empty.json", ""),
                   ("bom.json", b"\xef\xbb\xbf{}"), ("comment.json", '{"a": 1 /* c */}'), ("top-number.json", "1e400")]:
    put("json", name, text)
print("corpus written to", out)
