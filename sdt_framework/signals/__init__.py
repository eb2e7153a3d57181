"""Signal files: the kit every reader shares, a layer below the datasets.

A file format is a reader plugin (``ReaderSpec``, hook
``register_signal_readers``, the built-in ones under ``plugins/readers/``, one
format wholly in each); what several formats, datasets or commands share sits
here, and nothing here looks a registry up: the caller hands the table of
readers down (``reader_for(file, registry.signal_readers())``, as xarray's
``guess_engine`` asks the engines ``list_engines`` gives it).

Public API
----------
SignalInfo, DataFileError, SignalTypeError
    What a reader says of each signal of a file; how a file is refused
    (:mod:`.rules`, :mod:`.errors`: the checks every reader applies).
reader_for, scan_file, read_signal, known_formats
    A file's reader among those handed down, and reading through it (:mod:`.files`).
open_signal, FileSignal
    One signal of one file, its rate and units settled against the file's:
    what ``sdt degrade``, ``sdt features extract``, ``sdt validate-noise
    --recording`` and a twin pair's sides read (:mod:`.one_signal`).
Channel, ChannelSignal, Subchannel
    A recorder file of several channels, each on its own clock (:mod:`.channels`).
read_csv_signal, CsvSignal
    The one CSV rule (header, orientation, time column, values), used by the
    CSV reader, NLN-EMP's CSVs and a pair's columns (:mod:`.csv_rule`).
on_even_grid, EvenSignal
    A time base measured from timestamps, resampled when uneven (:mod:`.timebase`).
quote, brief
    A piece of a user's file in a message, never a whole line (:mod:`.tokens`).

channel_reader, part_channel, axis_variable
    The reader of a file of channels, the channel of a part, an axis's signal name (``32:x``).
Cost, available_memory, free_disk, building, human_bytes, human_seconds, memory_cause
    What the machine has and what a command costs (:mod:`.sizes`).
file_samples, DEGRADE_BYTES_PER_SAMPLE, FEATURES_BYTES_PER_SAMPLE, TWIN_BYTES_PER_SAMPLE, ...
    A signal file's samples from its header, the measured bytes per sample of each
    command (:mod:`.file_sizes`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..lazy import lazy_exports

if TYPE_CHECKING:
    from .channels import Channel, ChannelSignal, Subchannel, axis_variable, part_channel
    from .csv_rule import CsvSignal, read_csv_signal
    from .errors import DataFileError, SignalTypeError
    from .file_sizes import (
        DEGRADE_BYTES_PER_SAMPLE,
        FEATURES_BYTES_PER_SAMPLE,
        TWIN_BYTES_PER_IDE_BYTE,
        TWIN_BYTES_PER_SAMPLE,
        file_samples,
    )
    from .files import channel_reader, known_formats, read_signal, reader_for, scan_file
    from .one_signal import FileSignal, open_signal
    from .rules import SignalInfo
    from .sizes import (
        Cost,
        available_memory,
        building,
        free_disk,
        human_bytes,
        human_seconds,
        memory_cause,
    )
    from .timebase import EvenSignal, on_even_grid
    from .tokens import brief, quote

#: public name -> the submodule that defines it, loaded on first use (PEP 562): a reader
#: plugin that needs SignalInfo does not load pyarrow
_WHERE = {
    "Channel": "channels",
    "ChannelSignal": "channels",
    "Subchannel": "channels",
    "axis_variable": "channels",
    "part_channel": "channels",
    "CsvSignal": "csv_rule",
    "read_csv_signal": "csv_rule",
    "DataFileError": "errors",
    "SignalTypeError": "errors",
    "DEGRADE_BYTES_PER_SAMPLE": "file_sizes",
    "FEATURES_BYTES_PER_SAMPLE": "file_sizes",
    "TWIN_BYTES_PER_IDE_BYTE": "file_sizes",
    "TWIN_BYTES_PER_SAMPLE": "file_sizes",
    "file_samples": "file_sizes",
    "channel_reader": "files",
    "known_formats": "files",
    "read_signal": "files",
    "reader_for": "files",
    "scan_file": "files",
    "FileSignal": "one_signal",
    "open_signal": "one_signal",
    "SignalInfo": "rules",
    "Cost": "sizes",
    "available_memory": "sizes",
    "building": "sizes",
    "free_disk": "sizes",
    "human_bytes": "sizes",
    "human_seconds": "sizes",
    "memory_cause": "sizes",
    "EvenSignal": "timebase",
    "on_even_grid": "timebase",
    "brief": "tokens",
    "quote": "tokens",
}

__all__ = [
    "DEGRADE_BYTES_PER_SAMPLE",
    "FEATURES_BYTES_PER_SAMPLE",
    "TWIN_BYTES_PER_IDE_BYTE",
    "TWIN_BYTES_PER_SAMPLE",
    "Channel",
    "ChannelSignal",
    "Cost",
    "CsvSignal",
    "DataFileError",
    "EvenSignal",
    "FileSignal",
    "SignalInfo",
    "SignalTypeError",
    "Subchannel",
    "available_memory",
    "axis_variable",
    "brief",
    "building",
    "channel_reader",
    "file_samples",
    "free_disk",
    "human_bytes",
    "human_seconds",
    "known_formats",
    "memory_cause",
    "on_even_grid",
    "open_signal",
    "part_channel",
    "quote",
    "read_csv_signal",
    "read_signal",
    "reader_for",
    "scan_file",
]

__getattr__, __dir__ = lazy_exports(__name__, _WHERE, globals())
