"""``study --reproduce I --out FILE`` refuses to replace an existing file without ``--force`` (review item 7),
as ``init`` does; the user's file is left unchanged."""

from __future__ import annotations

from pathlib import Path

from mechverify.cli import main

LIFT = Path(__file__).resolve().parents[1] / "examples" / "lead_screw_lift" / "design.toml"
ARGS = ["--vary", "components.lift.mass=normal:15 kg:1 kg", "-n", "4", "--seed", "2", "--serial", "--no-progress",
        "--reproduce", "1", "--out"]


def test_existing_out_needs_force(tmp_path, capsys):
    mine = tmp_path / "mine.toml"
    mine.write_text("# my notes\n")
    assert main(["study", str(LIFT), *ARGS, str(mine)]) == 2
    assert "exists; pass --force" in capsys.readouterr().err
    assert mine.read_text() == "# my notes\n"
    assert main(["study", str(LIFT), *ARGS, str(mine), "--force"]) == 0
    assert "[components" in mine.read_text()


def test_force_only_with_out(capsys):
    assert main(["study", str(LIFT), "--vary", "components.lift.mass=10 kg:20 kg:2", "--force"]) == 2
    assert "--force: only with --reproduce" in capsys.readouterr().err
