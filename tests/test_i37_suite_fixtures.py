"""The suite's own fixtures (issue 37: the suite made cheaper keeps what its tests rely on)."""

from __future__ import annotations

import os
import stat


def test_tmp_path_is_a_new_empty_private_folder_under_the_base(tmp_path, tmp_path_factory):
    """Each test's tmp_path: a new folder, empty, only its owner's, named after the test,
    under the run's base folder (where pytest keeps the last three runs)."""
    assert tmp_path.is_dir() and list(tmp_path.iterdir()) == []
    assert tmp_path.parent == tmp_path_factory.getbasetemp()
    assert stat.S_IMODE(os.stat(tmp_path).st_mode) == 0o700
    assert tmp_path.name.startswith("test_tmp_path_is_a_new_empty_")
