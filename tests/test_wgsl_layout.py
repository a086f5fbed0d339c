"""The WGSL structs and ids agree with rtfgu.layout: one source of truth, checked twice.

On the CPU: every named offset of layout.RECORDS picks the right value out of the rows
that compile_scene writes, and the generated struct puts every field at that offset.
On the GPU: a compute shader reads every field of every generated struct from buffers
filled straight from layout arrays, and the ids from the generated constants; what it
writes back must be the values numpy put there.
"""
from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest

from rtfgu import layout
from rtfgu.cameras import OrthographicCamera, PinholeCamera
from rtfgu.float3 import Float3
from rtfgu.lights import PointLight
from rtfgu.materials import SHADER_NAMES, Transparent
from rtfgu.scene import Scene
from rtfgu.shapes import Plane, Sphere, Triangle
from rtfgu.wgsl import structs

from wgsl_support import wgpu_device  # noqa: F401  (fixture)


def _scene(camera) -> Scene:
    scene = Scene(camera)
    # The 02562 glossy shader (Phong, then refraction): every field of the Material row is its own.
    material = Transparent(ior=1.33, ka=0.125, kd=0.75, ks=1.0, cs=(0.25, 0.5, 0.75), exp=17.0,
                           emission=(0.01, 0.02, 0.03))
    scene.shapes.append(Plane((1, 2, 3), (0, 2, 0), (0.1, 0.2, 0.3), material))
    scene.shapes.append(Triangle((0, 0, 0), (1, 0, 0), (0, 1, 0), (0.4, 0.5, 0.6)))
    scene.shapes.append(Sphere((4, 5, 6), 0.7, (0.7, 0.8, 0.9)))
    scene.lights.append(PointLight((-1, 3, 2), (5, 6, 7)))
    return scene


def _field(row, name, record):
    width, fields = layout.RECORDS[record]
    for field, components, column in fields:
        if field == name:
            return list(row[column:column + components])
    raise KeyError(name)


def test_named_offsets_pick_the_compiled_values():
    camera = PinholeCamera((2, 1.5, 2), (0, 0.5, 0), (0, 1, 0), d=1.25, aspect=1.5)
    scene = _scene(camera)
    flat = layout.compile_scene(scene, "float64")
    cam = flat.camera.ravel()
    assert _field(cam, "eye", "PinholeCamera") == [2, 1.5, 2]
    assert _field(cam, "d", "PinholeCamera") == [1.25]
    assert _field(cam, "aspect", "PinholeCamera") == [1.5]
    for name in ("b1", "b2", "v"):
        expected = getattr(camera, name)
        assert _field(cam, name, "PinholeCamera") == [expected.x, expected.y, expected.z]
    assert _field(flat.table("plane")[0], "point", "Plane") == [1, 2, 3]
    assert _field(flat.table("plane")[0], "normal", "Plane") == [0, 2, 0]
    tri = scene.shapes[1]
    for name in ("v0", "e0", "e1", "n"):
        v = getattr(tri, name)
        assert _field(flat.table("triangle")[0], name, "Triangle") == [v.x, v.y, v.z]
    assert _field(flat.table("sphere")[0], "center", "Sphere") == [4, 5, 6]
    assert _field(flat.table("sphere")[0], "radius", "Sphere") == [0.7]
    m = flat.materials[0]
    assert _field(m, "color", "Material") == [0.1, 0.2, 0.3]
    assert _field(m, "specular", "Material") == [0.25, 0.5, 0.75]
    assert _field(m, "shininess", "Material") == [17.0]
    assert _field(m, "emission", "Material") == [0.01, 0.02, 0.03]
    assert _field(m, "ior", "Material") == [1.33]
    assert _field(m, "kd", "Material") == [0.75]
    assert _field(m, "ambient", "Material") == [0.125, 0.125, 0.125]     # ka times Ambient() (ls 1, white)
    assert _field(flat.lights["point_light"][0], "position", "PointLight") == [-1, 3, 2]
    assert _field(flat.lights["point_light"][0], "intensity", "PointLight") == [5, 6, 7]

    ortho = layout.compile_scene(_scene(OrthographicCamera(-1, 2, -3, 4, hither=0.5, yon=9)),
                                 "float64").camera.ravel()
    for name, value in (("left", -1), ("right", 2), ("bottom", -3), ("top", 4),
                        ("hither", 0.5), ("yon", 9), ("tmin", 1e-5)):
        assert _field(ortho, name, "OrthographicCamera") == [value]


@pytest.mark.parametrize("record", sorted(layout.RECORDS))
def test_pack_table_puts_each_value_in_its_fields_columns_and_zero_elsewhere(record):
    width, fields = layout.RECORDS[record]
    # Each component its own value (a Float3's x, y, z differ), none of them zero.
    values, expected, k = {}, np.zeros(width), 1.0
    for name, components, column in fields:
        if components == 3:
            values[name] = Float3(k, k + 0.25, k + 0.5)
            expected[column:column + 3] = (k, k + 0.25, k + 0.5)
        else:
            values[name] = k
            expected[column] = k
        k += 1.0
    objects = [SimpleNamespace(**values), SimpleNamespace(**values)]
    table = layout.pack_table(record, [layout.row_values(record, o) for o in objects], np.float32)
    assert table.shape == (2, width) and table.dtype == np.float32
    assert table.tolist() == [expected.tolist()] * 2
    assert layout.pack_table(record, [], np.float64).shape == (0, width)
    # A row built from the fields by name is the row read from an object holding them.
    built = layout.row_builder(record)(**values)
    assert built == layout.row_values(record, objects[0])
    assert layout.pack_table(record, [built], np.float32).tolist() == [expected.tolist()]
    with pytest.raises(TypeError):   # every field is named, none left to a default
        layout.row_builder(record)(**dict(list(values.items())[1:]))


def test_pack_table_refuses_a_vector_where_its_record_holds_a_number():
    obj = SimpleNamespace(center=Float3(1.0, 2.0, 3.0), radius=Float3(1.0))
    with pytest.raises((TypeError, ValueError)):
        layout.pack_table("Sphere", [layout.row_values("Sphere", obj)], np.float64)


# WGSL's alignment and size rules for the types the records use.
_ALIGN_SIZE = {"vec3f": (16, 12), "vec4f": (16, 16), "f32": (4, 4)}


@pytest.mark.parametrize("record", sorted(layout.RECORDS))
def test_generated_struct_puts_fields_at_layout_offsets(record):
    width, fields = layout.RECORDS[record]
    generated = structs.struct_fields(record)
    # Walk the generated fields with WGSL's rules, independently of the generator's own offsets.
    offset, align_max, placed = 0, 4, {}
    for name, wgsl_type, _ in generated:
        align, size = _ALIGN_SIZE[wgsl_type]
        offset = -(-offset // align) * align
        placed[name] = offset
        offset += size
        align_max = max(align_max, align)
    assert -(-offset // align_max) * align_max == 4 * width
    for name, components, column in fields:
        assert placed[name] == 4 * column, name
        assert dict((n, t) for n, t, _ in generated)[name] == ("vec3f" if components == 3 else "f32")


# Records read back per shader: one binding each, within WebGPU's guaranteed 12 uniform and
# 8 storage buffers per shader stage (the output buffer is one more).
RECORDS_PER_SHADER = 7


def _record_groups() -> list:
    records = list(layout.RECORDS)
    return [records[i:i + RECORDS_PER_SHADER] for i in range(0, len(records), RECORDS_PER_SHADER)]


def _readback_shader(space: str, records, with_ids: bool) -> tuple[str, list]:
    """A compute shader copying every field of two rows of each of ``records``, then (with
    ``with_ids``) the ids."""
    lines = [structs.constants_wgsl()]
    lines += [structs.struct_wgsl(record) for record in records]
    plan = []
    decl = "uniform" if space == "uniform" else "storage, read"
    for binding, record in enumerate(records):
        lines.append("@group(0) @binding(%d) var<%s> r%d: array<%s, 2>;" % (binding, decl, binding, record))
    lines.append("@group(0) @binding(%d) var<storage, read_write> out: array<f32>;" % len(records))
    body, k = [], 0
    for binding, record in enumerate(records):
        width, fields = layout.RECORDS[record]
        for row in range(2):
            for name, components, column in fields:
                for c in range(components):
                    access = "r%d[%d].%s%s" % (binding, row, name, "" if components == 1 else "[%d]" % c)
                    body.append("    out[%d] = %s;" % (k, access))
                    plan.append((record, row, column + c))
                    k += 1
    ids = ([(name.upper(), i) for i, name in SHADER_NAMES.items()]
           + [(name.upper(), i) for i, name in layout.SHAPE_KINDS.items()]
           + [(name.upper(), i) for i, name in layout.CAMERA_KINDS.items()]) if with_ids else []
    for name, value in ids:
        body.append("    out[%d] = f32(%s);" % (k, name))
        plan.append(("id", name, value))
        k += 1
    lines.append("@compute @workgroup_size(1)\nfn main() {\n%s\n}" % "\n".join(body))
    return "\n".join(lines), plan


@pytest.mark.parametrize("group", range(len(_record_groups())))
@pytest.mark.parametrize("space", ["uniform", "storage"])
def test_gpu_reads_every_field_where_layout_put_it(wgpu_device, space, group):
    import wgpu

    device = wgpu_device
    records = _record_groups()[group]
    source, plan = _readback_shader(space, records, with_ids=group == 0)
    rng = np.random.default_rng(4)
    rows = {record: rng.uniform(-100, 100, size=(2, layout.RECORDS[record][0])).astype(np.float32)
            for record in records}
    usage = (wgpu.BufferUsage.UNIFORM if space == "uniform" else wgpu.BufferUsage.STORAGE)
    entries = []
    for binding, record in enumerate(records):
        buffer = device.create_buffer_with_data(data=rows[record].tobytes(), usage=usage)
        entries.append({"binding": binding, "resource": {"buffer": buffer}})
    out = device.create_buffer(size=4 * len(plan),
                               usage=wgpu.BufferUsage.STORAGE | wgpu.BufferUsage.COPY_SRC)
    entries.append({"binding": len(records), "resource": {"buffer": out}})
    module = device.create_shader_module(code=source)
    pipeline = device.create_compute_pipeline(layout="auto",
                                              compute={"module": module, "entry_point": "main"})
    group = device.create_bind_group(layout=pipeline.get_bind_group_layout(0), entries=entries)
    encoder = device.create_command_encoder()
    compute = encoder.begin_compute_pass()
    compute.set_pipeline(pipeline)
    compute.set_bind_group(0, group)
    compute.dispatch_workgroups(1)
    compute.end()
    device.queue.submit([encoder.finish()])
    got = np.frombuffer(device.queue.read_buffer(out), dtype=np.float32)
    for value, entry in zip(got, plan):
        if entry[0] == "id":
            assert value == entry[2], entry
        else:
            record, row, column = entry
            assert value == rows[record][row, column], entry


def test_id_constants_come_from_the_layout():
    text = structs.constants_wgsl()
    for shader_id, name in SHADER_NAMES.items():
        assert "const %s: i32 = %d;" % (name.upper(), shader_id) in text
    assert "const FAR = %rf;" % float(layout.FAR) in text
    assert "const PI = %rf;" % math.pi in text


def test_a_scene_with_many_tables_keeps_to_webgpus_uniform_buffer_limit():
    """The noise scene binds more small tables than WebGPU's 12 uniform buffers per stage
    (Chromium refuses the pipeline otherwise): the largest go to storage, the rest stay."""
    from rtfgu.layout import compile_scene
    from rtfgu.scenes import SCENES
    from rtfgu.wgsl.assemble import MAX_UNIFORM_BUFFERS, assemble

    program = assemble(compile_scene(SCENES["suffern_31_noise"](), "float32"))
    uniform = [b for b in program.bindings if b.kind == "uniform"]
    assert len(uniform) + 1 <= MAX_UNIFORM_BUFFERS            # + the Uniforms at binding 0
    moved = [b for b in program.bindings if b.kind == "storage" and b.size <= 65536
             and b.name not in ("mesh_vertices", "mesh_faces", "mesh_normals", "mesh_uvs", "bvh_nodes")]
    assert moved and min(b.size for b in moved) >= max(b.size for b in uniform if b.name != "camera")
    assert len(uniform) + 1 == MAX_UNIFORM_BUFFERS             # only as many as needed moved
