"""Bad input files and lists end in ValueError naming the cause (docs/errors.md, "Limits"), before
any work, and Scene.from_json's message is the command line's for the same file: a scene file in
UTF-16, a FIFO, /dev/zero, a directory, too many speeds, a DMA file that is not a regular file, a
prony material without terms."""

import json
import os
import subprocess

import numpy as np
import pytest

import viscoroll as vr

MAX_SPEEDS = 100000  # viscoroll::limits::speeds
PAPER = {
    "material": {"model": "standard_linear_solid", "mu_d": 1e6, "nu": 0.5, "f": 9, "tau": 0.01},
    "roller": {"profile": "ellipsoid", "c1": 100, "c2": 7.98},
    "load": 10,
    "speeds": [0.1, 1.0],
    "method": "line",
}


def write(path, scene):
    path.write_text(json.dumps(scene))
    return path


def prony_dma(path, dma):
    return write(path, dict(PAPER, material={"model": "prony", "nu": 0.5, "dma": str(dma)}))


def bad_files(tmp_path):
    """(name, path) of scene files each command line and Python refuse."""
    utf16 = tmp_path / "utf16.json"
    utf16.write_bytes(json.dumps(PAPER).encode("utf-16"))  # with its byte order mark
    utf16_bare = tmp_path / "utf16le.json"
    utf16_bare.write_bytes(json.dumps(PAPER).encode("utf-16-le"))
    latin1 = tmp_path / "latin1.json"
    latin1.write_bytes(json.dumps(dict(PAPER, description="Gummi \xfc"),
                                  ensure_ascii=False).encode("latin-1"))
    fifo = tmp_path / "fifo.json"
    os.mkfifo(fifo)
    speeds = write(tmp_path / "speeds.json", dict(PAPER, speeds=[1.0] * (MAX_SPEEDS + 1)))
    no_terms = write(tmp_path / "terms.json", dict(PAPER, material={
        "model": "prony", "nu": 0.5, "g_inf": 1e6, "terms": []}))
    dma_dir = tmp_path / "dma_dir"
    dma_dir.mkdir()
    return [("utf-16", utf16), ("utf-16 without a mark", utf16_bare), ("latin-1", latin1),
            ("fifo", fifo), ("/dev/zero", "/dev/zero"), ("directory", tmp_path),
            ("too many speeds", speeds), ("no terms", no_terms),
            ("dma /dev/zero", prony_dma(tmp_path / "dma_zero.json", "/dev/zero")),
            ("dma directory", prony_dma(tmp_path / "dma_dir.json", dma_dir))]


CAUSES = {
    "utf-16": "scene file is not UTF-8 text (a UTF-16 byte order mark)",
    "utf-16 without a mark": "scene file is not UTF-8 text (a NUL byte at offset 1",
    "latin-1": "scene file is not UTF-8 text (byte 0xfc at offset",
    "fifo": "is a FIFO, not a regular file",
    "/dev/zero": "is a character device, not a regular file",
    "directory": "is a directory, not a scene file",
    "too many speeds": f"speeds has {MAX_SPEEDS + 1} values, over the limit of {MAX_SPEEDS}",
    "no terms": "material.terms is empty",
    "dma /dev/zero": "is a character device, not a regular file (a DMA CSV file must be one)",
    "dma directory": "is a directory, not a DMA CSV file",
}


def test_bad_scene_files_raise_the_command_lines_message(viscoroll_solve, tmp_path):
    for name, path in bad_files(tmp_path):
        with pytest.raises(ValueError) as error:
            vr.Scene.from_json(path)
        message = str(error.value)
        assert CAUSES[name] in message, name
        # A FIFO without a writer would block an open(): the command line must refuse it first.
        done = subprocess.run([str(viscoroll_solve), "--scene", str(path)], capture_output=True,
                              text=True, timeout=30, check=False)
        assert done.returncode == 2, (name, done.stderr)
        assert done.stdout == ""
        assert done.stderr == "viscoroll-solve: " + message + "\n", name


def test_speed_lists_are_numbers_within_the_limit():
    scene = vr.Scene(material=vr.StandardLinearSolid(mu_d=1.0, nu=0.5, f=9.0, tau=1.0),
                     roller=vr.Cylinder(radius=1.0), load=0.1)
    for call in (lambda v: vr.Scene(material=scene.material, roller=scene.roller, load=0.1,
                                    speeds=v),
                 lambda v: vr.sweep(scene, speeds=v)):
        with pytest.raises(ValueError, match=r"speeds = '0.1' is a string, not a number"):
            call("0.1")
        with pytest.raises(ValueError, match=r"speeds = b'0.1' is a string"):
            call(b"0.1")
        with pytest.raises(ValueError, match=f"speeds has {MAX_SPEEDS + 1} values, over the "
                                             f"limit of {MAX_SPEEDS}"):
            call(np.ones(MAX_SPEEDS + 1))
    # At the limit: accepted.
    assert len(vr.Scene(material=scene.material, roller=scene.roller, load=0.1,
                        speeds=np.zeros(MAX_SPEEDS)).speeds) == MAX_SPEEDS


def test_a_prony_material_needs_a_term():
    with pytest.raises(ValueError, match=r"len\(terms\) = 0 is outside the valid range "
                                         r"len\(terms\) >= 1"):
        vr.Prony(g_inf=1e6, nu=0.5, terms=[])
    assert len(vr.Prony(g_inf=1e6, nu=0.5, terms=[(1e6, 1e-3)]).terms) == 1


def test_no_message_is_empty_or_lost(tmp_path):
    """A file name that is not UTF-8 is read as the bytes it is, and shown escaped."""
    path = tmp_path / os.fsdecode(b"sc\xe8ne.json")
    path.write_bytes(b"\xff\xfe{")
    with pytest.raises(ValueError) as error:
        vr.Scene.from_json(path)
    message = str(error.value)
    assert message.endswith("sc\\xe8ne.json: scene file is not UTF-8 text (a UTF-16 byte order "
                            "mark); save it as UTF-8")
