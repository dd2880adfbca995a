"""Where the OpenSubdiv bridge is built, and that the folder is checked before a library in it is
trusted: the user's cache folder, for a source tree (an editable install) and an installed package
alike, since a package never writes into its own folder (issue 35, item 20);
``SYMDECOMP_BRIDGE_DIR`` over both."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from symdecomp.verify.opensubdiv import build as osd_build


@pytest.fixture
def environment(monkeypatch, tmp_path):
    monkeypatch.delenv(osd_build.BUILD_DIR_VARIABLE, raising=False)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    return monkeypatch


def _installed(monkeypatch, tmp_path) -> Path:
    """The bridge's folder as in site-packages: .../symdecomp/verify/opensubdiv, no pyproject.toml above."""
    here = tmp_path / "site-packages" / "symdecomp" / "verify" / "opensubdiv"
    here.mkdir(parents=True)
    monkeypatch.setattr(osd_build, "HERE", here)
    return here


def test_a_source_tree_builds_in_the_cache_folder_too(environment, tmp_path):
    assert (osd_build.HERE.parents[2] / "pyproject.toml").is_file()  # this checkout
    assert osd_build.build_dir() == tmp_path / "cache" / "symdecomp" / f"opensubdiv-bridge-{osd_build.BRIDGE_VERSION}"


def test_an_installed_package_builds_in_the_cache_folder(environment, tmp_path):
    _installed(environment, tmp_path)
    assert osd_build.build_dir() == tmp_path / "cache" / "symdecomp" / f"opensubdiv-bridge-{osd_build.BRIDGE_VERSION}"
    environment.setenv("XDG_CACHE_HOME", "relative/cache")  # not absolute: ignored, as the XDG specification says
    assert osd_build.build_dir() == Path.home() / ".cache" / "symdecomp" / f"opensubdiv-bridge-{osd_build.BRIDGE_VERSION}"


def test_a_read_only_source_tree_builds_in_the_cache_folder(environment, tmp_path):
    here = _installed(environment, tmp_path)
    (here.parents[2] / "pyproject.toml").write_text("")
    assert osd_build.build_dir().parent == tmp_path / "cache" / "symdecomp"
    if os.geteuid() == 0:
        environment.setattr(osd_build.os, "access", lambda path, mode: False)  # root may write anywhere: pretend not
    else:
        here.chmod(0o555)
    assert osd_build.build_dir().parent == tmp_path / "cache" / "symdecomp"


def test_the_variable_chooses_the_folder(environment, tmp_path):
    environment.setenv(osd_build.BUILD_DIR_VARIABLE, str(tmp_path / "mine"))
    assert osd_build.build_dir() == tmp_path / "mine"


def _use(monkeypatch, folder: Path) -> None:
    monkeypatch.setattr(osd_build, "BUILD_DIR", folder)
    monkeypatch.setattr(osd_build, "LIBRARY", folder / "libsymdecomp_osd.so")
    monkeypatch.setattr(osd_build, "STAMP", folder / "libsymdecomp_osd.stamp")


def test_a_new_folder_is_private_and_trusted(environment, tmp_path):
    _use(environment, tmp_path / "a" / "b")
    assert osd_build.check_build_dir(create=True) == tmp_path / "a" / "b"
    assert (tmp_path / "a" / "b").stat().st_mode & 0o777 == 0o700


@pytest.mark.parametrize("make, problem", [
    (lambda p: (p.mkdir(), p.chmod(0o775)), "may be written by other users"),
    (lambda p: (p.mkdir(), p.chmod(0o757)), "may be written by other users"),
    (lambda p: (p.with_name("real").mkdir(mode=0o700), p.symlink_to(p.with_name("real"))), "is not a folder"),
    (lambda p: p.write_text("a file"), "is not a folder"),
])
def test_a_folder_others_could_change_is_not_trusted(environment, tmp_path, make, problem):
    folder = tmp_path / "bridge"
    make(folder)
    _use(environment, folder)
    with pytest.raises(osd_build.BridgeBuildError, match=f"{problem}: not trusted; set {osd_build.BUILD_DIR_VARIABLE}"):
        osd_build.check_build_dir(create=True)
    assert not osd_build.is_current()  # a library there is never loaded without a rebuild, and the rebuild refuses
    with pytest.raises(osd_build.BridgeBuildError, match=problem):
        osd_build.build(force=True)


def test_a_folder_of_another_user_is_not_trusted(environment, tmp_path):
    folder = tmp_path / "bridge"
    folder.mkdir(mode=0o700)
    _use(environment, folder)
    uid = os.getuid()
    environment.setattr(osd_build.os, "getuid", lambda: uid + 1)
    with pytest.raises(osd_build.BridgeBuildError, match="belongs to another user"):
        osd_build.check_build_dir()
