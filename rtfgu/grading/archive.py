"""Submissions as untrusted archives: a folder, a zip file or a single file, unpacked into a
folder of regular files only.

Every entry is checked by where it lands once resolved (``Path.relative_to`` of the
destination, never a string prefix); links are ignored, in a zip (by the entry's mode bits)
and in a folder (never followed out of it); the number of entries and the bytes written are
capped, and a zip entry's bytes are counted while they are decompressed (its declared size
may lie), so a zip bomb costs at most ARCHIVE_BYTES of disk and a chunk of memory.
"""
from __future__ import annotations

import os
import shutil
import stat
import zipfile
from pathlib import Path

ARCHIVE_FILES = 500                    # entries of a submitted archive that are read at most
ARCHIVE_BYTES = 32 * 1024 * 1024       # decompressed bytes of a submitted archive at most
FILE_BYTES = 4 * 1024 * 1024           # bytes of one submitted file at most
NOTES = 20                             # notes about the submission's files in the result at most
NAME_CHARS = 100                       # characters of a submitted name a note quotes at most


def _name(name) -> str:
    """A submitted file name as a note quotes it: printable, and short (an entry's name is
    the student's to choose, up to 64 KB in a zip)."""
    text = "".join(c if c.isprintable() else "?" for c in str(name))
    return text if len(text) <= NAME_CHARS else text[:NAME_CHARS] + "..."


# --- the submission ----------------------------------------------------------------------

def unpack_submission(submission, tmp: Path, notes: list) -> Path:
    """A folder with the submission's regular files: a copy of the folder (links not
    followed), a zip extracted safely, or a single file."""
    submission = Path(submission)
    out = Path(tmp) / "submission"
    out.mkdir(parents=True, exist_ok=True)
    found = []
    if submission.is_dir():
        _copy_folder(submission, out, found)
    elif submission.is_file() and zipfile.is_zipfile(submission):
        _extract_zip(submission, out, found)
    elif submission.is_file():
        shutil.copyfile(submission, out / submission.name)
    else:
        raise ValueError("submission: %s is neither a folder, a zip file nor a file" % submission)
    if len(found) > NOTES:  # the first ones, and the last (why reading stopped, if it did)
        found = found[:NOTES - 1] + ["... and %d more notes like these about the submission's files"
                                     % (len(found) - NOTES)] + found[-1:]
    notes.extend(found)
    return out


def _copy_folder(folder: Path, out: Path, notes: list) -> None:
    total, count = 0, 0
    for root, dirs, files in os.walk(folder, followlinks=False):
        dirs[:] = [d for d in dirs if not os.path.islink(os.path.join(root, d)) and d != "__pycache__"]
        for name in files:
            path = Path(root) / name
            if path.is_symlink() or not path.is_file():
                notes.append("%s is a link; it was ignored" % _name(path.relative_to(folder)))
                continue
            count += 1
            size = path.stat().st_size
            if count > ARCHIVE_FILES or total + size > ARCHIVE_BYTES or size > FILE_BYTES:
                notes.append("the submission has more files or bytes than the grader reads; %s and "
                             "later files were ignored" % _name(path.relative_to(folder)))
                return
            total += size
            target = out / path.relative_to(folder)
            try:
                target.parent.mkdir(parents=True, exist_ok=True)
                shutil.copyfile(path, target, follow_symlinks=False)
            except OSError as error:
                notes.append("%s could not be read (%s); it was ignored" % (_name(path.relative_to(folder)),
                                                                          _name(error)))


def _extract_zip(archive: Path, out: Path, notes: list) -> None:
    """Entries checked one by one: a path that leaves ``out`` once resolved, a link, the
    entries past ARCHIVE_FILES and the bytes past ARCHIVE_BYTES (counted while reading: an
    entry's declared size may lie) are not extracted."""
    root = out.resolve()
    total = 0
    with zipfile.ZipFile(archive) as z:
        for count, info in enumerate(z.infolist(), start=1):
            if count > ARCHIVE_FILES:
                notes.append("the archive has more than %d entries; the rest were ignored" % ARCHIVE_FILES)
                return
            mode = info.external_attr >> 16
            if info.is_dir():
                continue
            if stat.S_ISLNK(mode):
                notes.append("%s is a link; it was ignored" % _name(info.filename))
                continue
            target = (root / info.filename).resolve()
            try:
                target.relative_to(root)
            except ValueError:
                notes.append("%s points outside the submission folder; it was ignored" % _name(info.filename))
                continue
            written = 0
            try:
                target.parent.mkdir(parents=True, exist_ok=True)
                with z.open(info) as source, open(target, "wb") as sink:
                    while True:
                        chunk = source.read(1 << 16)
                        if not chunk:
                            break
                        written += len(chunk)
                        total += len(chunk)
                        if written > FILE_BYTES or total > ARCHIVE_BYTES:
                            break
                        sink.write(chunk)
            except (OSError, zipfile.BadZipFile, NotImplementedError, RuntimeError) as error:
                notes.append("%s could not be unpacked (%s); it was ignored" % (_name(info.filename), _name(error)))
                continue
            if written > FILE_BYTES or total > ARCHIVE_BYTES:
                target.unlink()
                notes.append("the archive unpacks to more than %d MB (at %s); the rest was ignored"
                             % (ARCHIVE_BYTES // (1024 * 1024), _name(info.filename)))
                return


def find_files(assignment, folder: Path) -> dict:
    """relpath -> path of each of the assignment's files found in ``folder``: by its path in
    the package (shapes/sphere.py, also under rtfgu/), else by its file name anywhere."""
    found = {}
    candidates = [p for p in sorted(folder.rglob("*")) if p.is_file() and not p.is_symlink()
                  and "__pycache__" not in p.parts and "__MACOSX" not in p.parts]
    for relpath in assignment.files:
        by_path = [p for p in candidates if p.relative_to(folder).as_posix().endswith(relpath)]
        by_name = [p for p in candidates if p.name == Path(relpath).name]
        pick = (by_path or by_name or [None])[0]
        if pick is not None:
            found[relpath] = pick
    return found
