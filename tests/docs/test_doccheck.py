"""The documented-command checker judges outputs as intended: noise passes, changes do not."""

from __future__ import annotations

import signal
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))

from tools.doccheck.compare import expectation, normalise, problems
from tools.doccheck.extract import FileStep, steps

TABLE = (
    "┏━━━━━━━━━┳━━━━━━━━┓",
    "┃ sensor  ┃     LR ┃",
    "┡━━━━━━━━━╇━━━━━━━━┩",
    "│ adxl345 │ 0.3663 │",
    "└─────────┴────────┘",
)


def test_numbers_and_column_widths_are_noise():
    assert normalise("│ adxl345 │ 0.3663 │") == normalise("│ adxl345   │  0.41 │")
    assert normalise("900 runs in 83 s") == normalise("900 runs in 1234 s")
    assert normalise("Δ -0.044 [-0.046, -0.041]") == "Δ # [#, #]"
    assert normalise("real\t0m6.0s") == normalise("real\t1m6.629s")
    assert normalise("adxl345 ch1 SF12/125") == "adxl345 ch1 SF12/#"


def test_a_rerun_with_other_figures_passes():
    expected = expectation("sdt x", TABLE)
    rerun = "\n".join(line.replace("0.3663", "0.40") for line in TABLE)
    assert problems(expected, 0, rerun) == []


def test_a_lost_row_a_changed_word_a_traceback_or_status_fail():
    expected = expectation("sdt x", TABLE)
    assert problems(expected, 0, "\n".join(TABLE[:3] + TABLE[4:]))  # row lost
    assert problems(expected, 0, "\n".join(TABLE).replace("adxl345", "adxl357"))
    assert problems(expected, 0, "\n".join(TABLE) + "\nTraceback (most recent call last):")
    assert problems(expected, 1, "\n".join(TABLE))


def test_documented_status_is_read_from_echo_or_an_error_line():
    shown = ("error: sensor 'adxl345': target rate above the recording's", "exit 2")
    expected = expectation('sdt degrade p.npy --fs 2000; echo "exit $?"', shown)
    assert (expected.command, expected.status) == ("sdt degrade p.npy --fs 2000", 2)
    assert expected.lines == shown[:1]
    assert expectation("sdt sensors show x", ("error: part 'x': no",)).status == 2
    assert expectation("sdt budget", ("paper8: 8 features",)).status == 0


def test_prose_rewrapped_by_the_terminal_width_still_matches():
    expected = expectation("sdt x", ("skipped sensor a: sensor 'a'", "samples at 26667 Hz"))
    assert problems(expected, 0, "skipped sensor a: sensor 'a' samples at\n26667 Hz") == []


def test_blocks_notes_and_shown_files_are_read(tmp_path):
    doc = tmp_path / "d.md"
    doc.write_text(
        "<!-- doccheck: file=a.toml -->\n```toml\nx = 1\n```\n\n"
        '<!-- doccheck: skip reason="needs hardware" -->\n```\n$ sdt a\nout\n$ sdt b\n```\n'
    )
    found = steps(doc, tmp_path)
    assert isinstance(found[0], FileStep) and found[0].content == "x = 1\n"
    assert [(c.text, c.output, c.line) for c in found[1:]] == [
        ("sdt a", ("out",), 8),
        ("sdt b", (), 10),
    ]
    assert found[1].notes == {"skip": "", "reason": "needs hardware"}


def test_a_slow_block_keeps_the_slow_time_limit_when_every_block_runs(tmp_path, monkeypatch):
    """``--mode all`` gives a ``slow`` block the slow limit: it stopped full benchmarks at 300 s."""
    from tools.doccheck import runner

    limits: dict[str, float] = {}
    monkeypatch.setattr(runner, "judge", lambda c, s, t: limits.setdefault(c.text, t))
    doc = tmp_path / "d.md"
    doc.write_text(
        "```\n$ echo quick\nquick\n```\n\n<!-- doccheck: slow -->\n```\n$ echo long\nlong\n```\n"
    )
    found = steps(doc, tmp_path)
    for mode in ("all", "slow"):
        limits.clear()
        list(runner.run_doc(found, mode, tmp_path))
        assert limits == {
            "echo quick": runner.FAST_TIMEOUT_S if mode == "all" else runner.SLOW_TIMEOUT_S,
            "echo long": runner.SLOW_TIMEOUT_S,
        }


def test_repaste_moves_figures_and_keeps_the_documents_choice_of_lines():
    """Shown lines take the printed figures in order; an elision stays, a line left out
    of the document stays out, and a shown line whose words moved is listed, untouched
    (and then only table rows move: wrapped prose could match the wrong line)."""
    from tools.doccheck.repaste import repaste

    shown = ("900 runs in 83 s", "...", "│ adxl345 │ 0.3663 │", "verdict: worse")
    printed = ["900 runs in 110 s", "Motor-2 table", "│ adxl345 │ 0.4100 │", "verdict: better"]
    new, unmatched = repaste(shown, printed)
    assert new == ["900 runs in 83 s", "...", "│ adxl345 │ 0.4100 │", "verdict: worse"]
    assert unmatched == ["verdict: worse"]
    # every line matched: prose takes its figures too
    assert repaste(shown[:3], printed)[0] == ["900 runs in 110 s", "...", "│ adxl345 │ 0.4100 │"]


def test_repaste_takes_no_line_from_another_machines_table():
    """A name with a digit (Motor-4, ch1) is a word when pasting: the Motor-2 row that
    the checker would accept is not pasted over a Motor-4 row."""
    from tools.doccheck.repaste import repaste

    shown = ("Macro F1, Motor-4", "│ adxl345 │ 0.3663 │")
    printed = [
        "Macro F1, Motor-2",
        "│ adxl345 │ 0.2000 │",
        "Macro F1, Motor-4",
        "│ adxl345 │ 0.4100 │",
    ]
    assert repaste(shown, printed) == (["Macro F1, Motor-4", "│ adxl345 │ 0.4100 │"], [])


def test_repaste_refuses_a_folder_without_a_dump_and_an_unknown_document(tmp_path, capsys):
    """Either is one error line and exit 2, before any document is read or written."""
    from tools.doccheck.repaste import main

    (tmp_path / "notes.txt").write_text("not a dump")
    assert main([str(tmp_path)]) == 2
    assert capsys.readouterr().err == (
        f"error: {tmp_path} holds no dump: run python -m tools.doccheck --mode all --dump "
        f"{tmp_path} first\n"
    )
    assert main([str(tmp_path), "docs/nope.md"]) == 2
    assert "not a checked document: docs/nope.md" in capsys.readouterr().err


def test_documents_side_by_side_keep_their_order_and_their_own_cpu(tmp_path):
    """``--jobs 2``: each document's commands in order, each command's CPU its own.

    The busy command (0.5 s of CPU) ends while the sleep beside it still runs;
    summing the checker's finished children instead would charge the sleep
    with the busy command's CPU.
    """
    from tools.doccheck.__main__ import _run_side_by_side

    busy = "python3 -c \"import time; exec('while time.process_time() < 0.5: pass')\""
    (tmp_path / "a.md").write_text(f"```\n$ {busy}\n$ echo a\na\n```\n")
    (tmp_path / "b.md").write_text("```\n$ sleep 1.5\n$ echo b\nb\n```\n")
    selected = {name: steps(tmp_path / name, tmp_path) for name in ("a.md", "b.md")}
    results = list(_run_side_by_side(selected, "all", tmp_path / "cache", jobs=2))
    assert {r.status for r in results} == {"passed"}
    for doc in ("a.md", "b.md"):
        assert [r.command.line for r in results if r.command.doc == doc] == [2, 3]
    cpu = {r.command.text: r.cpu for r in results}
    assert cpu[busy] >= 0.45
    assert cpu["sleep 1.5"] < 0.2


def test_a_command_past_its_time_limit_is_stopped_and_an_unknown_document_refused(tmp_path, capsys):
    """The time limit kills the command's whole session and says so; a document name
    that holds no command is one line and exit 2, not an empty pass."""
    from tools.doccheck.__main__ import main
    from tools.doccheck.sandbox import Sandbox

    status, printed, _, _ = Sandbox(tmp_path, tmp_path, tmp_path).run("sleep 30", 80, 1.0)
    assert status == -1 and "(stopped after 1 s)" in printed
    before = signal.getsignal(signal.SIGTERM)
    assert main(["--mode", "fast", "docs/nosuch.md"]) == 2
    assert capsys.readouterr().err.startswith("error: no such document: docs/nosuch.md;")
    # main() puts back the caller's SIGTERM handler: a test run after it in the same
    # process must see its own (this failed CI once, its handler exiting pytest's worker)
    assert signal.getsignal(signal.SIGTERM) is before
