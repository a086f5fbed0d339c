"""The entry of a test's interpreter (``python -I -S boot.py PACKAGE PROBES SITE FD PROBE...``):
put the student package, the probes and the site-packages on the path, run one probe, and
write its JSON answer to the pipe FD. It imports nothing of the grader: it runs next to the
student's code, in the sandbox rtfgu.grading.sandbox builds.

PROBE is ``check ASSIGNMENT SLUG`` (a test's observe function) or ``render SCENE WIDTH
HEIGHT`` (a homework image with the student's code; 0 keeps the scene's own size).
"""
import importlib
import json
import os
import sys

SUBMODULES = ("float3", "ray", "cameras", "shapes", "material", "lights", "shading", "scene",
              "renderer", "image", "scenes")


def _observe(kind, args):
    from rtfgu_checks import checks_for

    if kind == "check":
        assignment, slug = args
        check = next(c for c in checks_for(assignment) if c.slug == slug)
        modules = tuple(getattr(check, "modules", ()))
        return check.observe, modules
    if kind == "render":
        name, width, height = args[0], int(args[1]), int(args[2])

        def observe(rt):
            fn = rt.scenes.get_scene(name)
            w, h = fn.size
            image = rt.renderer.render_reference(fn(), width or w, height or h)
            return {"image": image.tolist()}
        return observe, ()
    raise ValueError("unknown probe %r" % kind)


def main(argv) -> None:
    package, probes, site_dirs, fd = argv[1:5]
    sys.path[:] = [package, probes] + [d for d in site_dirs.split(os.pathsep) if d] + \
        [p for p in sys.path if p != os.path.dirname(os.path.abspath(__file__))]
    fd = int(fd)
    from rtfgu_checks.child import describe_exception

    try:
        observe, modules = _observe(argv[5], argv[6:])
        rt = importlib.import_module("rtfgu")
        if not os.path.abspath(rt.__file__).startswith(os.path.abspath(package) + os.sep):
            raise RuntimeError("rtfgu was imported from %s, not from the student package" % rt.__file__)
        for name in SUBMODULES + modules:
            importlib.import_module("rtfgu." + name)
        data = observe(rt)
    except BaseException as error:  # the student's import or code failed as a whole
        data = {"error": describe_exception(error)}
    payload = memoryview(json.dumps(data).encode())
    while payload:
        n = os.write(fd, payload[:1 << 16])
        payload = payload[n:]
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(0)


if __name__ == "__main__":
    main(sys.argv)
