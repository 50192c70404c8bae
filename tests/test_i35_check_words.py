"""Issue 35, items 7 and 8: `gyro check` on signed pairs that books print as
magnitudes, and slips named only when the ratio matches them to the tolerance.

Independent references, by hand: a rotor of 2.5 kg with k = 35 mm (J = m k^2)
spinning at 1725 rpm and precessing at 48 rpm has the gyroscopic moment
M = J omega Omega; its bearings (rails) 200 mm apart share it as +M / L and -M / L.
"""

from __future__ import annotations

import math
import textwrap
from pathlib import Path
from types import SimpleNamespace

from click.testing import CliRunner

from gyro_cli.checking import check, matching
from gyro_cli.checking.expected import parse_expected
from gyro_cli.checking.tolerance import parse_tolerance
from gyro_cli.cli import main

RPM = 2 * math.pi / 60
J = 2.5 * 0.035 ** 2
COUPLE = J * 1725 * RPM * 48 * RPM  # about 2.781 N m
RAIL = COUPLE / 0.200  # about 13.90 N: one rail pressed by it, the other relieved


def rails_file(tmp_path: Path, expected: str, tolerance: str = "") -> Path:
    """A gyroscopic_torque problem asking for the couple's share on the two rails."""
    path = tmp_path / "rails.yaml"
    path.write_text(textwrap.dedent("""\
        id: rails
        title: Rotor on two rails
        kind: gyroscopic_torque
        given:
          mass: 2.5 kg
          k_axial: 35 mm
          spin: 1725 rpm
          precession: 48 rpm
          bearing_spacing: 200 mm
        find: {couple_forces: N}
        """) + (f"tolerance: {tolerance}\n" if tolerance else "") +
        f"expected:\n  couple_forces: {expected}\n")
    return path


def test_item07_magnitudes_fail_naming_the_sign_convention(tmp_path: Path) -> None:
    size = f"{RAIL:.4g} N"
    result = check.check_file(str(rails_file(tmp_path, f"[{size}, {size}]")))
    first, second = result.answers
    assert first.passed and not second.passed
    assert second.slip is not None
    assert "the order" not in second.slip
    assert "is the size of the computed B" in second.slip
    assert "sign convention for couple_forces" in second.slip
    assert "+M / L and -M / L" in second.slip  # the kind's own words for its signs
    assert "`tolerance: 1% magnitude`" in second.slip


def test_item07_magnitudes_pass_with_a_magnitude_tolerance(tmp_path: Path) -> None:
    size = f"{RAIL:.4g} N"
    path = rails_file(tmp_path, f"[{size}, {size}]", tolerance="1% magnitude")
    result = check.check_file(str(path))
    assert [a.passed for a in result.answers] == [True, True]
    out = CliRunner().invoke(main, ["check", str(path)])
    assert out.exit_code == 0, out.output


def test_item07_signed_values_pass_and_a_real_swap_is_still_the_order(tmp_path: Path) -> None:
    signed = f"[{RAIL:.4g} N, {-RAIL:.4g} N]"
    assert check.check_file(str(rails_file(tmp_path, signed))).status == "pass"
    swapped = f"[{-RAIL:.4g} N, {RAIL:.4g} N]"
    result = check.check_file(str(rails_file(tmp_path, swapped)))
    assert result.status == "fail"
    # sizes equal, signs swapped: each value is its partner's size too, the sign names it
    assert all(a.slip and a.slip.startswith("the sign") for a in result.answers)
    # an ordered pair of different sizes swapped: the order, as before
    reported = SimpleNamespace(si_values=[5131.0, 2869.0], labels=["outer", "inner"],
                               unit="N", si_unit="N")
    values = parse_expected(["2869 N", "5131 N"], "force", "expected.wheel_reactions")
    lines = matching.compare("wheel_reactions", values, parse_tolerance("1%", "force"),
                             reported, convention="[outer, inner]")
    assert lines[0].slip is not None and lines[0].slip.startswith("the order: 2869 N")


def test_item07_the_bad_magnitude_tolerance_is_one_line_exit_2(tmp_path: Path) -> None:
    size = f"{RAIL:.4g} N"
    path = rails_file(tmp_path, f"[{size}, {size}]", tolerance="'-1% magnitude'")
    out = CliRunner().invoke(main, ["check", str(path)])
    assert out.exit_code == 2
    assert len([line for line in out.stderr.splitlines() if line.strip()]) == 1


def test_item08_no_slip_named_when_the_ratio_misses_the_tolerance() -> None:
    # 57.1 is 0.34% from 180/pi: within the old 0.5% floor, outside a 0.1% tolerance
    assert abs(57.1 / (180 / math.pi) - 1) < 0.005
    assert matching.diagnose(1.0, 57.1, 0.001) is None
    # a force off by a missing bank angle (cos 11.5 deg): nothing to name at any tolerance
    assert matching.diagnose(100.0, 100.0 / math.cos(math.radians(11.5)), 1.0) is None
    # the sign and a power of ten follow the same rule
    assert matching.diagnose(1.0, -1.003, 0.001) is None
    assert matching.diagnose(1.0, 10.03, 0.001) is None


def test_item08_true_slips_still_named() -> None:
    slip = matching.diagnose(1.0, 180 / math.pi, 0.001)
    assert slip is not None and "180/pi" in slip
    assert matching.diagnose(1.0, 57.1, 0.01) is not None  # 0.34% within a 1% tolerance
    slip = matching.diagnose(2.0, -2.0, 0.0)  # exactly the sign, at an exact tolerance
    assert slip is not None and slip.startswith("the sign")


def test_item08_check_names_no_slip_off_the_tolerance(tmp_path: Path) -> None:
    # a rail force quoted 57.1 times too small: not 180/pi to the file's 0.1%
    wrong = f"[{RAIL / 57.1:.6g} N, {-RAIL:.6g} N]"
    result = check.check_file(str(rails_file(tmp_path, wrong, tolerance="0.1%")))
    first = result.answers[0]
    assert not first.passed and first.slip is None
    assert "off by" in first.message
    right_slip = f"[{RAIL / (180 / math.pi):.6g} N, {-RAIL:.6g} N]"
    result = check.check_file(str(rails_file(tmp_path, right_slip, tolerance="0.1%")))
    assert result.answers[0].slip is not None and "180/pi" in result.answers[0].slip
