#!/usr/bin/env python3
"""Writes the hand-made hostile inputs of corpus/ (run from anywhere; rewrites them).

Each file states one defect that once crashed, hung or over-allocated a reader
(issue 14): overflowing accessor counts and offsets, buffer views past their buffer,
lying image headers, out-of-range references, deep nesting, duplicate keys, indices and enums of the wrong
type or range; and for the
image codecs (issue 26) length fields past the bytes present and EXR channel names that
are not R, G, B, A. Inputs a fuzzer finds are copied into corpus/ as they are, next to
these. tests/core/image_hostile_test.cpp reads the image ones by name.
"""
import base64
import json
import pathlib
import struct
import zlib

HERE = pathlib.Path(__file__).resolve().parent / "corpus"


def data_uri(raw: bytes) -> str:
    return "data:application/octet-stream;base64," + base64.b64encode(raw).decode()


TRIANGLE = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
PNG_HEADER = lambda w, h: (b"\x89PNG\r\n\x1a\n\x00\x00\x00\x0dIHDR" + struct.pack(">II", w, h)
                           + b"\x08\x06\x00\x00\x00" + b"\x00" * 4)


def gltf(accessors, views, extra_bin=b"", **extra):
    doc = {
        "asset": {"version": "2.0"},
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "buffers": [{"uri": data_uri(TRIANGLE + extra_bin), "byteLength": len(TRIANGLE) + len(extra_bin)}],
        "bufferViews": views,
        "accessors": accessors,
    }
    doc.update(extra)
    return json.dumps(doc).encode()


def vec3(count, offset=0, view=0):
    return {"bufferView": view, "byteOffset": offset, "componentType": 5126, "type": "VEC3", "count": count}


VIEW = [{"buffer": 0, "byteLength": 36}]


def textured(image: bytes, view: dict, texture=None):
    doc = json.loads(gltf([vec3(3)], VIEW + [view], image))
    doc["meshes"][0]["primitives"][0]["material"] = 0
    doc["materials"] = [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}]
    doc["textures"] = [texture or {"source": 0}]
    doc["images"] = [{"bufferView": 1, "mimeType": "image/png"}]
    return json.dumps(doc).encode()


def glb_bin_past_end():
    body = b'{"asset": {"version": "2.0"}, "buffers": [{"byteLength": 24}]}'
    body += b" " * (-len(body) % 4)
    data = b"\0" * 16
    total = 12 + 8 + len(body) + 8 + len(data)
    return (b"glTF" + struct.pack("<II", 2, total) + struct.pack("<I", len(body)) + b"JSON" + body
            + struct.pack("<I", len(data) + 8) + b"BIN\0" + data)


def png_chunk(kind: bytes, data: bytes, length=None) -> bytes:
    size = len(data) if length is None else length
    return struct.pack(">I", size) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


def png(width, height, idat: bytes, extra=b"") -> bytes:
    ihdr = png_chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    return b"\x89PNG\r\n\x1a\n" + ihdr + extra + png_chunk(b"IDAT", idat) + png_chunk(b"IEND", b"")


def exr_attr(name: str, kind: str, value: bytes, size=None) -> bytes:
    return (name.encode() + b"\0" + kind.encode() + b"\0"
            + struct.pack("<i", len(value) if size is None else size) + value)


def exr_header(channels, width, height, compression=0, extra=b""):
    names = sorted(channels)
    chlist = b"".join(n.encode() + b"\0" + struct.pack("<i", 2) + b"\0" * 4 + struct.pack("<ii", 1, 1)
                      for n in names) + b"\0"
    window = struct.pack("<4i", 0, 0, width - 1, height - 1)
    return (b"\x76\x2f\x31\x01" + struct.pack("<I", 2) + exr_attr("channels", "chlist", chlist)
            + exr_attr("compression", "compression", bytes([compression]))
            + exr_attr("dataWindow", "box2i", window) + exr_attr("displayWindow", "box2i", window)
            + exr_attr("lineOrder", "lineOrder", b"\0")
            + exr_attr("pixelAspectRatio", "float", struct.pack("<f", 1))
            + exr_attr("screenWindowCenter", "v2f", struct.pack("<2f", 0, 0))
            + exr_attr("screenWindowWidth", "float", struct.pack("<f", 1)) + extra + b"\0")


def exr(channels, width, height, extra=b"", chunk_size=None, offsets=None):
    """A scanline OpenEXR of FLOAT channels {name: value} (one value per channel), written by
    hand so names, sizes and offsets can lie. Chunks hold one line (NONE compression)."""
    header = exr_header(channels, width, height, 0, extra)
    row = b"".join(struct.pack("<f", channels[n]) * width for n in sorted(channels))
    first = len(header) + 8 * height
    lines = [struct.pack("<ii", y, len(row) if chunk_size is None else chunk_size) + row
             for y in range(height)]
    table = offsets or [first + y * len(lines[0]) for y in range(height)]
    return header + b"".join(struct.pack("<Q", o) for o in table) + b"".join(lines)


RGB = {"R": 0.75, "G": 0.5, "B": 0.25}


def images():
    layered = {"diffuse." + k: v for k, v in RGB.items()}
    return {
        # A 1,262-byte PNG whose text chunk claims 2 GiB (libpng allocated it before reading).
        "png_chunk_length_huge.png": png(4, 4, zlib.compress(b"\0" * 52),
                                         png_chunk(b"tEXt", b"x" * 1200, 0x7FFFFFF0))[:1262],
        # An 8000x8000 header over 1 KB of pixel data: no deflate stream inflates that far.
        "png_idat_short.png": png(8000, 8000, zlib.compress(b"\0" * 4000)),
        "exr_attribute_huge.exr": exr(RGB, 4, 4, extra=exr_attr("comments", "string", b"x" * 16, 0x7FFFFFF0)),
        "exr_offset_outside.exr": exr(RGB, 4, 4, offsets=[1 << 40] * 4),
        "exr_chunk_size_huge.exr": exr(RGB, 4, 4, chunk_size=0x7FFFFFF0),
        # 8000x8000 in ZIP chunks of 16 lines, each a 1-byte chunk: 500 bytes cannot hold it.
        "exr_window_huge.exr": exr_window_huge(),
        # Channel names: B, G, R are stored sorted (B first); a layer's names carry its prefix;
        # X, Y, Z are not colour channels at all.
        "exr_bgr.exr": exr(RGB, 4, 4),
        "exr_layered.exr": exr(layered, 4, 4),
        "exr_xyz.exr": exr({"X": 0.75, "Y": 0.5, "Z": 0.25}, 4, 4),
        "exr_named_as.png": exr(RGB, 4, 4),
    }


def exr_window_huge():
    header = exr_header(RGB, 8000, 8000, compression=3)
    chunks = 500
    first = len(header) + 8 * chunks
    table = b"".join(struct.pack("<Q", first + 9 * i) for i in range(chunks))
    return header + table + b"".join(struct.pack("<ii", 16 * i, 1) + b"\0" for i in range(chunks))


def main():
    g = {
        "accessor_count_wraps.gltf": gltf([vec3(1537228672809129302)], VIEW),
        "accessor_offset_wraps.gltf": gltf([vec3(3, 18446744073709551600)], VIEW),
        "accessor_count_2_32.gltf": gltf([vec3(4294967296)], VIEW),
        "view_offset_plus_length_wraps.gltf": gltf(
            [vec3(3)], [{"buffer": 0, "byteOffset": 9223372036854775808, "byteLength": 9223372036854775808}]),
        "unbacked_count_2_31.gltf": gltf([{"componentType": 5126, "type": "VEC3", "count": 2147483648}], VIEW),
        "stride_below_element.gltf": gltf([vec3(3)], [{"buffer": 0, "byteLength": 36, "byteStride": 4}]),
        "image_view_past_buffer.gltf": textured(PNG_HEADER(4, 4), {"buffer": 0, "byteOffset": 36, "byteLength": 100000}),
        "image_header_huge.gltf": textured(PNG_HEADER(100000, 100000), {"buffer": 0, "byteOffset": 36, "byteLength": 33}),
        "texture_source_missing.gltf": textured(PNG_HEADER(4, 4), {"buffer": 0, "byteOffset": 36, "byteLength": 33},
                                                {"source": 9}),
        "texture_sampler_missing.gltf": textured(PNG_HEADER(4, 4), {"buffer": 0, "byteOffset": 36, "byteLength": 33},
                                                 {"source": 0, "sampler": 4}),
        "extras_nested_deep.gltf": b'{"asset": {"version": "2.0", "extras": ' + b"[" * 5000 + b"]" * 5000 + b"}}",
        "duplicate_key.gltf": b'{"asset": {"version": "2.0"}, "nodes": [], "nodes": [{}]}',
        "node_cycle.gltf": b'{"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"children": [1]}, {"children": [0]}]}',
        # Indices, enums and fixed-length arrays of the wrong type or range (gltf_checks.cpp):
        # tinygltf would wrap, default or keep them.
        "index_2_32_plus_1.gltf": gltf([vec3(3)], VIEW, nodes=[{"mesh": 4294967297}]),
        "index_fractional.gltf": gltf([vec3(3)], VIEW, scenes=[{"nodes": [0.5]}]),
        "index_string.gltf": gltf([vec3(3)], [{"buffer": "0", "byteLength": 36}]),
        "byte_offset_negative.gltf": gltf([vec3(3, -4)], VIEW),
        "matrix_15_numbers.gltf": gltf([vec3(3)], VIEW, nodes=[{"mesh": 0, "matrix": [1] * 15}]),
        "base_color_2_numbers.gltf": gltf([vec3(3)], VIEW, materials=[
            {"pbrMetallicRoughness": {"baseColorFactor": [1, 1]}, "doubleSided": "yes"}]),
        "wrap_s_12345.gltf": textured(PNG_HEADER(4, 4), {"buffer": 0, "byteOffset": 36, "byteLength": 33},
                                      {"source": 0, "sampler": 0}).replace(
            b'"images"', b'"samplers": [{"wrapS": 12345}], "images"'),
        "uri_nul.gltf": gltf([vec3(3)], VIEW, images=[{"uri": "a.bin%00.png"}]),
        "glb_bin_chunk_past_end.glb": glb_bin_past_end(),
        "glb_chunk_length_huge.glb": b"glTF" + struct.pack("<II", 2, 40) + struct.pack("<I", 0xFFFFFFF0) + b"JSON" + b"{}" + b" " * 18,
    }
    c = {
        "duplicate_key.json": b'{"render": {"width": 64, "width": 128}}',
        "nested_deep.json": b'{"description": ' + b"[" * 5000 + b"]" * 5000 + b"}",
        "stereo_too_wide.json": b'{"taa": {"mode": "tscmaa"}, "tscmaa": {"eyes": 2}, "render": {"width": 8192}}',
        "scene_outside.json": b'{"scene": {"gltf": "../../etc/passwd"}}',
        "frames_huge.json": b'{"script": {"frames": 18446744073709551615}}',
    }
    t = {
        "duplicate_key.json": b'{"format": "taa-track", "version": 1, "fps": 30, "fps": 60}',
        "nested_deep.json": b'{"camera": ' + b"[" * 5000 + b"]" * 5000 + b"}",
        "huge_numbers.csv": b"time,px,py,pz,qx,qy,qz,qw\n1e308,1e308,0,0,0,0,0,1\n1e309,0,0,0,0,0,0,1\n",
        "ragged.csv": b"time,px,py,pz,qx,qy,qz,qw\n0,0,0\n,,,,,,,,,,,,\n",
    }
    for sub, files in (("gltf", g), ("case", c), ("track", t), ("image", images())):
        (HERE / sub).mkdir(parents=True, exist_ok=True)
        for name, data in files.items():
            (HERE / sub / name).write_bytes(data)


if __name__ == "__main__":
    main()
