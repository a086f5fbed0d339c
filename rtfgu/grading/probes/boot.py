"""The entry of a test's interpreter: ``python -I -S boot.py PACKAGE PROBES SITE FD OPTIONS PROBE...``.

It puts the folder holding the student's ``rtfgu`` (PACKAGE), the folder holding this probe
package (PROBES) and the site-packages (SITE, joined by os.pathsep) on the path, runs one
probe with the student's package, and writes the probe's JSON answer to the pipe FD. OPTIONS
is JSON (rtfgu.grading.timeouts.boot_options): ``dump`` [fd, seconds], where faulthandler
writes every thread's traceback shortly before the time limit, and ``stopped``, the student
functions that an earlier test's time limit stopped, which raise instead of running
(support.stop_functions). It imports nothing of the grader: it runs next to the student's code.

PROBE is one of
  ``probe MODULE FUNCTION KWARGS``  probes.run(MODULE, FUNCTION, json.loads(KWARGS), rt);
  ``check ASSIGNMENT SLUG``         the probe of that test, looked up in ``tests.json`` beside
                                    this file (written when the probes are copied);
  ``render SCENE WIDTH HEIGHT``     a homework image by the lecture layer (0: its own size).
"""
import faulthandler
import importlib
import json
import os
import sys

SUBMODULES = ("float3", "ray", "cameras", "shapes", "hit_info", "brdfs", "btdfs", "materials", "lights", "tracers", "scene",
              "renderer", "image", "scenes", "textures")
HERE = os.path.dirname(os.path.abspath(__file__))
PACKAGE_NAME = os.path.basename(HERE)


def _probe(kind, args):
    """(module, function, kwargs) of the probe the command line names."""
    if kind == "probe":
        return args[0], args[1], json.loads(args[2]) if len(args) > 2 else {}
    if kind == "check":
        with open(os.path.join(HERE, "tests.json")) as f:
            module, function, kwargs = json.load(f)[args[0]][args[1]]
        return module, function, kwargs
    if kind == "render":
        return "images", "render_homework", {"scene": args[0], "width": int(args[1]), "height": int(args[2])}
    raise ValueError("unknown probe %r" % kind)


def main(argv) -> None:
    package, probes, site_dirs, fd = argv[1:5]
    sys.path[:] = [package, probes] + [d for d in site_dirs.split(os.pathsep) if d] + \
        [p for p in sys.path if p != HERE]
    fd = int(fd)
    options = json.loads(argv[5])
    if options.get("dump"):
        dump_fd, seconds = options["dump"]
        faulthandler.dump_traceback_later(float(seconds), file=int(dump_fd))
    argv = argv[:5] + argv[6:]
    probe_package = importlib.import_module(PACKAGE_NAME)
    support = importlib.import_module(PACKAGE_NAME + ".support")
    describe_exception = support.describe_exception

    try:
        module, function, kwargs = _probe(argv[5], argv[6:])
        rt = importlib.import_module("rtfgu")
        if not os.path.abspath(rt.__file__).startswith(os.path.abspath(package) + os.sep):
            raise RuntimeError("rtfgu was imported from %s, not from the student package" % rt.__file__)
        for name in SUBMODULES:
            importlib.import_module("rtfgu." + name)
        support.stop_functions(options.get("stopped", []))
        data = probe_package.run(module, function, kwargs, rt)
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
