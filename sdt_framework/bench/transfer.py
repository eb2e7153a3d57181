"""Cross-chain runs: a classifier trained on one chain's features and tested on another's.

A plant holds years of labelled piezo recordings; its new nodes carry a MEMS
part. ``[benchmark] transfer`` asks what a model trained on the first costs
on the second: each entry is ``TRAIN -> TEST``, the classifier and its scaler
fitted on the training chain's features of the training runs, scored on the
test chain's features of the test runs. Same split, seeds and noise draws as
the ordinary runs, so ``S -> S`` *is* the ordinary run of S and ``A -> B``
differs from ``B -> B`` only in the training chain.

Syntax (names as in ``--sensors``, a part's mode in brackets):

- ``wilcoxon-786b10 -> adxl345,adxl357``: one pair per test chain;
- ``reference -> *``: the benchmark's reference to every other sensor (``*``:
  every sensor of the benchmark but the first training chain);
- ``wilcoxon-786b10+adxl345 -> adxl345``: train on a mix (both chains'
  training windows, in that order), the usual mitigation.

A transfer run is labelled ``sensor = "TRAIN -> TEST"`` (so Table 4, the
report and ``sdt compare`` treat it as one more row: ``sdt compare DIR
--baseline adxl345`` gives what training on the reference costs an ADXL345
node) with ``train_sensor`` and ``test_sensor`` beside it.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

from ..errors import SDTError, one_line
from ..parts import split_names
from ..specs import SensorSpec

__all__ = ["Transfer", "parse_transfers"]


@dataclass(frozen=True)
class Transfer:
    """One cross-chain pair: canonical sensor names."""

    train: tuple[str, ...]
    test: str

    @property
    def train_label(self) -> str:
        """The training chain(s), ``+``-joined."""
        return "+".join(self.train)

    @property
    def label(self) -> str:
        """``TRAIN -> TEST``: the run's row label."""
        return f"{self.train_label} -> {self.test}"


#: at most this many characters of a user's entry are echoed in a message
ECHO = 100


def _echo(entry: str) -> str:
    """``entry`` as a message quotes it: whole if short, else its start and its size.

    A 2000-sensor entry was echoed whole (16 KB on one line) by every message.
    """
    if len(entry) <= ECHO:
        return repr(entry)
    names = len(split_names(entry.partition("->")[2])) if "->" in entry else 0
    count = f", {names} test chains" if names else ""
    return f"{one_line(entry, ECHO)!r} ({len(entry)} characters{count})"


def _resolve(name: str, entry: str, lookup: Callable[[str], SensorSpec], reference: str) -> str:
    name = name.strip()
    if not name:
        raise SDTError(f"transfer {_echo(entry)}: an empty chain name; write 'TRAIN -> TEST'")
    if name == "reference":
        name = reference
    try:
        return lookup(name).name
    except SDTError as exc:
        raise SDTError(f"transfer {_echo(entry)}: {one_line(exc, 400)}") from None


def parse_transfers(
    entries: Sequence[str],
    lookup: Callable[[str], SensorSpec],
    reference: str,
    sensors: Sequence[str],
) -> list[Transfer]:
    """The pairs named by ``entries``, in order, each once.

    ``lookup`` resolves a name to its spec (the registry's), ``reference`` is
    what ``reference`` means, ``sensors`` what ``*`` expands to (less the
    first training chain).

    Raises
    ------
    SDTError
        An unknown chain, an empty side, or a pair without any chain.
    """
    out: list[Transfer] = []
    for entry in entries:
        left, _, right = entry.partition("->")
        train = tuple(_resolve(n, entry, lookup, reference) for n in left.split("+"))
        if len(set(train)) != len(train):
            raise SDTError(f"transfer {_echo(entry)}: a training chain is named twice")
        names = split_names(right) if right.strip() != "*" else None
        if names == []:
            raise SDTError(
                f"transfer {_echo(entry)}: no test chain after '->'; write 'TRAIN -> TEST' "
                f"(several: 'TRAIN -> A,B'; every other sensor: 'TRAIN -> *')"
            )
        tests = (
            [s for s in sensors if s != train[0]]
            if names is None
            else [_resolve(n, entry, lookup, reference) for n in names]
        )
        if not tests:
            raise SDTError(f"transfer {_echo(entry)}: '*' leaves no sensor besides {train[0]}")
        for test in tests:
            pair = Transfer(train, test)
            if pair not in out:
                out.append(pair)
    return out
