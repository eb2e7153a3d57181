"""Stage 2 of a benchmark: one classifier run on one train/test split.

Standardisation is fitted on the training windows only and applied to both
sides; the estimator is built fresh from its spec with the run's seed. A
classifier that raises is recorded as ``status="error"`` with its message, so
one broken plugin never stops a sweep.

Two rules keep a stored result right (SPEC section 9):

- Every fit and predict runs with one BLAS/OpenMP thread, whichever process
  runs it (``--jobs 1`` in the main process, loky workers, Dask workers).
  Thread count changes the floating-point summation order inside BLAS, and
  the MLP's training amplifies that into different predictions; with the
  limit, results depend only on (data, configuration, seed). Parallelism comes
  from running runs side by side (``--jobs``), not from threads inside a fit.
- A SIGINT during a fit always ends the run with ``KeyboardInterrupt``, even
  when the estimator catches it (scikit-learn's MLP does, and would return a
  half-trained model): an interrupted fit never becomes a result.
"""

from __future__ import annotations

import time
import warnings
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from sklearn.exceptions import ConvergenceWarning
from sklearn.metrics import confusion_matrix, f1_score, precision_recall_fscore_support
from sklearn.preprocessing import StandardScaler
from threadpoolctl import get_cached_controller

from ..specs import ClassifierSpec
from .interrupt import no_swallowed_interrupt

__all__ = ["RunResult", "RunTask", "fit_predict", "recording_counts", "run_classifier"]


@dataclass(frozen=True)
class RunTask:
    """One (machine, scenario, sensor, classifier, repeat) run, with its data."""

    key: str
    labels: dict[str, Any]  # machine, scenario, sensor, feature_set, classifier, repeat, seed
    classifier: ClassifierSpec
    seed: int
    classes: tuple[str, ...]
    x_train: np.ndarray
    y_train: np.ndarray  # integer codes into ``classes``
    x_test: np.ndarray
    y_test: np.ndarray
    test_recordings: np.ndarray | None = None  # recording_id of each test window


@dataclass
class RunResult:
    """Scores of one run (or its error)."""

    key: str
    labels: dict[str, Any]
    macro_f1: float
    n_train: int
    n_test: int
    fit_seconds: float
    status: str
    error: str = ""
    per_class: list[dict[str, Any]] = field(default_factory=list)
    confusion: list[list[int]] = field(default_factory=list)
    classes: list[str] = field(default_factory=list)
    # [recording_id, true class, predicted class, count] for each non-zero pair
    per_recording: list[list[Any]] = field(default_factory=list)

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready form (stored per run for resuming)."""
        return {
            "key": self.key,
            "labels": self.labels,
            "macro_f1": self.macro_f1,
            "n_train": self.n_train,
            "n_test": self.n_test,
            "fit_seconds": self.fit_seconds,
            "status": self.status,
            "error": self.error,
            "per_class": self.per_class,
            "confusion": self.confusion,
            "classes": self.classes,
            "per_recording": self.per_recording,
        }


def fit_predict(
    spec: ClassifierSpec, seed: int, x_train: np.ndarray, y_train: np.ndarray, x_test: np.ndarray
) -> tuple[np.ndarray, StandardScaler]:
    """Standardise on the training set only, fit, and predict the test set.

    Runs with one BLAS/OpenMP thread and raises ``KeyboardInterrupt`` if a
    SIGINT arrived during the fit, even one the estimator swallowed.
    """
    scaler = StandardScaler().fit(x_train)
    # Built first: building imports the estimator's module, and the thread
    # limit below reaches only the native libraries loaded when it starts. The
    # controller of those libraries is threadpoolctl's cached one, found again
    # when a module was imported since (a native library comes with an import):
    # finding them at every run took 3 ms, as long as a small fit.
    estimator = spec.build(seed=seed)
    one_thread = get_cached_controller().limit(limits=1)
    with one_thread, no_swallowed_interrupt(), warnings.catch_warnings():
        # A capped iteration count is part of the paper's protocol, not a user error.
        warnings.simplefilter("ignore", ConvergenceWarning)
        # The MLP's note on a swallowed Ctrl-C: the interrupt is re-raised instead.
        warnings.filterwarnings("ignore", message="Training interrupted by user")
        # A small training set (node samples: a third of the channel windows) is smaller
        # than the MLP's fixed batch; scikit-learn then uses the whole set, as it says.
        warnings.filterwarnings("ignore", message="Got `batch_size` less than 1 or larger")
        estimator.fit(scaler.transform(x_train), y_train)
        predicted = np.asarray(estimator.predict(scaler.transform(x_test))).astype(int)
    return predicted, scaler


def recording_counts(
    recordings: np.ndarray, y_true: np.ndarray, y_pred: np.ndarray, classes: tuple[str, ...]
) -> list[list[Any]]:
    """Confusion counts per test recording: ``[recording_id, true, predicted, count]`` rows.

    Only non-zero pairs are listed; summed over recordings they give the run's
    confusion matrix. They let ``sdt compare`` resample the test set by
    recording, which a single Macro F1 per run cannot.
    """
    names, group = np.unique(np.asarray(recordings, dtype=str), return_inverse=True)
    n = len(classes)
    flat = (group * n + y_true) * n + y_pred
    codes, counts = np.unique(flat, return_counts=True)
    rec, rest = np.divmod(codes, n * n)
    true, pred = np.divmod(rest, n)
    return [
        [str(names[r]), classes[t], classes[p], int(c)]
        for r, t, p, c in zip(rec, true, pred, counts, strict=True)
    ]


def run_classifier(task: RunTask) -> RunResult:
    """Fit, predict and score one run; a classifier exception becomes status=error."""
    n_train, n_test = len(task.y_train), len(task.y_test)
    start = time.perf_counter()
    try:
        predicted, _ = fit_predict(
            task.classifier, task.seed, task.x_train, task.y_train, task.x_test
        )
    except Exception as exc:
        return RunResult(
            task.key,
            task.labels,
            float("nan"),
            n_train,
            n_test,
            time.perf_counter() - start,
            "error",
            f"{type(exc).__name__}: {exc}",
        )
    seconds = time.perf_counter() - start
    codes = list(range(len(task.classes)))
    macro = f1_score(task.y_test, predicted, average="macro", zero_division=0)  # SPEC section 7
    precision, recall, f1, support = precision_recall_fscore_support(
        task.y_test, predicted, labels=codes, zero_division=0
    )
    per_class = [
        {
            "class": name,
            "precision": float(p),
            "recall": float(r),
            "f1": float(f),
            "support": int(s),
        }
        for name, p, r, f, s in zip(task.classes, precision, recall, f1, support, strict=True)
    ]
    matrix = confusion_matrix(task.y_test, predicted, labels=codes)
    by_recording = (
        recording_counts(task.test_recordings, task.y_test, predicted, task.classes)
        if task.test_recordings is not None
        else []
    )
    return RunResult(
        task.key,
        task.labels,
        float(macro),
        n_train,
        n_test,
        seconds,
        "ok",
        per_class=per_class,
        confusion=matrix.tolist(),
        classes=list(task.classes),
        per_recording=by_recording,
    )
