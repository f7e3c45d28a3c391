"""A minimal PEP 517 build backend for this pure-Python package: build_wheel zips casteljau/ (its
.py files and the py.typed marker) with the dist-info files a wheel needs (METADATA, WHEEL,
RECORD), and adds casteljau/_build_tree.py, which records where the shared library of the source
tree's build folder is (SOURCE/build/libcasteljau.so.0), so that `pip install ./python` after a
cmake build finds the library without installing it. No dependencies."""
import base64
import hashlib
import os
import zipfile

NAME, VERSION = "casteljau", "0.1.0"
HERE = os.path.dirname(os.path.abspath(__file__))
DIST_INFO = "%s-%s.dist-info" % (NAME, VERSION)


def _files():
    root = os.path.join(HERE, NAME)
    for dirpath, _, names in os.walk(root):
        for n in sorted(names):
            if (n.endswith(".py") or n == "py.typed") and n != "_build_tree.py":
                full = os.path.join(dirpath, n)
                yield os.path.relpath(full, HERE).replace(os.sep, "/"), open(full, "rb").read()
    library = os.path.join(os.path.dirname(HERE), "build", "libcasteljau.so.0")
    yield NAME + "/_build_tree.py", ('"""Written by the wheel backend: the source tree\'s build folder library."""\n'
                                     "LIBRARY = %r\n" % library).encode()


def _metadata():
    readme = open(os.path.join(HERE, "README.md"), encoding="utf-8").read()
    return ("Metadata-Version: 2.1\nName: %s\nVersion: %s\nSummary: ctypes binding of the casteljau C API\n"
            "Requires-Python: >=3.8\nDescription-Content-Type: text/markdown\n\n%s" % (NAME, VERSION, readme)).encode()


def _wheel_file():
    return b"Wheel-Version: 1.0\nGenerator: casteljau _wheel_backend\nRoot-Is-Purelib: true\nTag: py3-none-any\n"


def _record_line(path, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return "%s,sha256=%s,%d" % (path, digest, len(data))


def get_requires_for_build_wheel(config_settings=None):
    return []


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    d = os.path.join(metadata_directory, DIST_INFO)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, "METADATA"), "wb") as f:
        f.write(_metadata())
    with open(os.path.join(d, "WHEEL"), "wb") as f:
        f.write(_wheel_file())
    return DIST_INFO


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    name = "%s-%s-py3-none-any.whl" % (NAME, VERSION)
    entries = list(_files()) + [(DIST_INFO + "/METADATA", _metadata()), (DIST_INFO + "/WHEEL", _wheel_file())]
    record = "\n".join([_record_line(p, d) for p, d in entries] + [DIST_INFO + "/RECORD,,", ""]).encode()
    with zipfile.ZipFile(os.path.join(wheel_directory, name), "w", zipfile.ZIP_DEFLATED) as z:
        for p, d in entries:
            z.writestr(p, d)
        z.writestr(DIST_INFO + "/RECORD", record)
    return name
