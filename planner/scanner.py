"""Scanner profiles: the :class:`Scanner` data class and the catalogue shipped as data.

The catalogue lives in ``planner/data/scanners.toml`` (one ``[[scanner]]`` table per
profile, each with its source). A user's own profile uses the same file format.
"""

from __future__ import annotations

import difflib
import json
import math
import os
import re
import tomllib
from collections.abc import Mapping
from dataclasses import asdict, dataclass, field, fields, replace
from functools import cache
from importlib import resources
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from planner._array import as_float_array
from planner.atomic import write_text_atomic
from planner.errors import InputError
from planner.ranges import RANGES, check_number
from planner.reading import user_file
from planner.signal import (
    DEFAULT_RANGE_EXPONENT,
    DEFAULT_RANGING_EXPONENT,
    DEFAULT_REFERENCE_REFLECTANCE,
    reach_exponent,
    relative_signal,
    signal_ranging_rms_mm,
    signal_reach_m,
)

__all__ = [
    "DEFAULT_SCANNER",
    "Preset",
    "Scanner",
    "catalogue",
    "check_profile_name",
    "installed_profile_path",
    "load_scanner",
    "read_scanner_file",
    "user_profile_dir",
    "user_profiles",
]

#: The scanner of Voroshilov & Karachentsev's worked example (m_S = 4 mm, 60 µrad): the
#: default everywhere a scanner is not given (CLI, dashboard, report, ``plan()``).
DEFAULT_SCANNER = "leica-4mm-60urad"
#: Where a cloud-to-cloud registration starts when the scanner gives no pre-alignment: the
#: operator picks three or more pairs of common points on the two clouds (REGISTER 360's,
#: SCENE's and CloudCompare's manual alignment), each off by about the clouds' spacing and
#: the eye's judgement at 10–30 m. Assumed: 30 mm per axis and 0.1° (360″) of heading
#: (30 mm over a 20 m spread of picks); the basin each link is checked for
#: (:mod:`planner.pipeline.network.linkcheck`) is 3 × these.
MANUAL_START_POSITION_MM = 30.0
MANUAL_START_HEADING_ARCSEC = 360.0


@dataclass(frozen=True)
class Preset:
    """One resolution / quality setting of a scanner, named as its maker names it.

    Parameters
    ----------
    name : str
        The maker's name of the setting (e.g. the RTC360's "medium", a Focus' "1/4, 4x").
    step_mm_at_10m : float
        Point spacing at 10 m square to the beam [mm].
    rate_hz : float or None
        Points measured per second at this setting (a quality setting that measures each
        point longer lowers it); None: the scanner's ``measurement_rate_hz``.
    scan_s : float or None
        The maker's stated duration of a full-dome scan at this setting [s]; None: the
        points of the dome over the rate (:mod:`planner.fieldwork`).
    """

    name: str
    step_mm_at_10m: float
    rate_hz: float | None = None
    scan_s: float | None = None

    def __post_init__(self) -> None:
        who = f"preset {self.name!r}"
        if not isinstance(self.name, str) or not self.name.strip():
            raise InputError("a scanner preset needs a name (the maker's name of the setting)")
        for key, rng in (
            ("step_mm_at_10m", "step_mm_at_10m"),
            ("rate_hz", "measurement_rate_hz"),
            ("scan_s", "scan_s"),
        ):
            if key == "step_mm_at_10m" or getattr(self, key) is not None:
                object.__setattr__(self, key, _number(getattr(self, key), f"{who}: {key}", rng))


@dataclass(frozen=True, kw_only=True)
class Scanner:
    """Accuracy figures and limits of one terrestrial laser scanner.

    Parameters
    ----------
    name : str
        Catalogue key (lower case, no spaces by convention).
    range_rms_mm : float
        Constant part ``a`` of the ranging RMS ``m_S = a + b·D`` [mm]; > 0.
    angle_rms_arcsec : float
        RMS of the horizontal angle ``m_β`` [″]; > 0.
    range_ppm : float, default 0
        Distance-proportional part ``b`` of the ranging RMS [ppm = mm/km]; >= 0.
    vertical_angle_rms_arcsec : float or None, default None
        RMS of the tilt (vertical angle) ``m_ν`` [″]; None means the same as horizontal.
    step_mm_at_10m : float, default 2.0
        Scan step (point spacing on a surface square to the beam) at 10 m [mm]. Sossa:
        1–3 mm is typical, 2 mm is the paper's choice.
    min_range_m, max_range_m : float, default 1.0 and 120.0
        Usable slope-distance range [m]; ``0 <= min < max``.
    vertical_fov_deg : (float, float), default (-45, 90)
        Lowest and highest beam elevation [deg] (270° panoramic field).
    measurement_rate_hz : float or None
        Points per second, if known.
    levelling_rms_arcsec : float or None
        Accuracy of the dual-axis compensator (how well the vertical axis is levelled,
        per axis) [″]. A scanner with one is *levelled*: eq. 4 uses it as ``m_ν0``, the 3-D
        model as the tilt of the vertical axis, and registration fixes the two tilts (4
        parameters instead of 6). None: no compensator; eq. 4 uses ``m_ν0 = m_ν`` as the
        paper's Table 2 does, and so does the 3-D model for the tilt.
    tilt_sensor_rms_arcsec : float or None
        Accuracy of the tilt the scanner records with every scan (its inclinometer or IMU,
        per axis) [″], for a scanner without a compensator that levels it. Registration
        software that uses the readings holds the network's vertical by all of them, not by
        the first scan's (:meth:`PlanSettings.tilt_model
        <planner.pipeline.inputs.requirements.PlanSettings.tilt_model>`). None: no reading.
    beam_divergence_mrad : float or None
        Full-angle beam divergence [mrad] (the beam's growth with distance).
    beam_exit_mm : float or None
        Beam diameter at the exit window [mm].
    prealign : "vis" or None
        What the scanner gives between set-ups for the registration to start from: "vis",
        its own tracking of the walk from one set-up to the next (Leica's visual-inertial
        system, VIS), which pre-aligns each scan to the one before it; None: nothing — the
        operator pre-aligns each pair in the software by picking common points (the cloud
        links start from :data:`MANUAL_START_POSITION_MM`, :data:`MANUAL_START_HEADING_ARCSEC`).
    prealign_position_mm, prealign_heading_arcsec : float or None
        The pre-alignment's error, per horizontal axis and of the heading [mm, ″], where the
        profile states one (:attr:`start_error`).
    registration : "targets", "cloud", "hybrid" or None
        How scans of this scanner are usually registered (e.g. cloud to cloud for a
        scanner whose software registers by its own tracking and the clouds); None:
        targets.
    presets : tuple of Preset
        The maker's resolution / quality settings (``[[scanner.preset]]`` tables); the
        plan picks one (:meth:`choose_preset`) and times the scans with it.
    default_preset : str or None
        The setting a crew uses when nothing asks for another (the profile's
        ``step_mm_at_10m`` is its step).
    sector_scan : bool, default True
        Whether the scanner can scan a horizontal sector only; one that cannot scans the
        full dome at every station, and is timed so.
    imaging_s : float, default 0
        Time of the station's images (HDR panorama) after the scan [s], when imaging is on.
    setup_min : float or None
        Time to set up, level and take down the scanner at a station [min] (the catalogue
        says where each figure comes from), used where the plan's settings give none
        (:meth:`~planner.pipeline.inputs.requirements.PlanSettings.station_setup_min`);
        None: the generic :data:`~planner.pipeline.inputs.requirements.GENERIC_SETUP_MIN`.
    reference_reflectance : float or None
        The reflectance [0–1] the ranging figures ``a + b·D`` are stated on (None:
        :data:`planner.signal.DEFAULT_REFERENCE_REFLECTANCE`); a darker surface or a
        slanting beam returns less signal and ranges noisier (:mod:`planner.signal`).
    ranging_exponent : float or None
        k of the ranging noise's growth as the signal falls, ``m_S ∝ q^(−k)`` (a lab
        calibration at several reflectances fits it, :mod:`planner.calibration`); None:
        :data:`planner.signal.DEFAULT_RANGING_EXPONENT`.
    range_reflectance : float or None
        The reflectance [0–1] ``max_range_m`` is stated on (None: the reference one).
    dark_range_m, dark_reflectance : float or None
        A second reach the datasheet states, on a darker surface [m, 0–1]: with the first
        it gives the reach's fall with the signal (:func:`planner.signal.reach_exponent`);
        None: the range equation's ½.
    label, source, notes : str
        Display name; where the figures come from; which values are assumptions.
    """

    name: str
    range_rms_mm: float
    angle_rms_arcsec: float
    range_ppm: float = 0.0
    vertical_angle_rms_arcsec: float | None = None
    step_mm_at_10m: float = 2.0
    min_range_m: float = 1.0
    max_range_m: float = 120.0
    vertical_fov_deg: tuple[float, float] = (-45.0, 90.0)
    measurement_rate_hz: float | None = None
    levelling_rms_arcsec: float | None = None
    tilt_sensor_rms_arcsec: float | None = None
    beam_divergence_mrad: float | None = None
    beam_exit_mm: float | None = None
    prealign: str | None = None
    prealign_position_mm: float | None = None
    prealign_heading_arcsec: float | None = None
    registration: str | None = None
    presets: tuple[Preset, ...] = ()
    default_preset: str | None = None
    sector_scan: bool = True
    imaging_s: float = 0.0
    setup_min: float | None = None
    reference_reflectance: float | None = None
    ranging_exponent: float | None = None
    range_reflectance: float | None = None
    dark_range_m: float | None = None
    dark_reflectance: float | None = None
    label: str = ""
    source: str = "user-defined"
    notes: str = ""
    extra: Mapping[str, Any] = field(default_factory=dict, compare=False, repr=False)

    def __post_init__(self) -> None:
        if not isinstance(self.name, str) or not self.name.strip():
            raise InputError("Scanner name must be a non-empty text, e.g. name='my-p20'")
        who = f"Scanner {self.name!r}"
        # each figure's range (planner.ranges.RANGES); the optional ones may be None
        figures = {
            "range_rms_mm": "range_rms_mm",
            "range_ppm": "range_ppm",
            "angle_rms_arcsec": "angle_rms_arcsec",
            "step_mm_at_10m": "step_mm_at_10m",
            "max_range_m": "max_range_m",
            "min_range_m": "min_range_m",
            "imaging_s": "imaging_s",
        }
        optional = {
            "vertical_angle_rms_arcsec": "angle_rms_arcsec",
            "measurement_rate_hz": "measurement_rate_hz",
            "levelling_rms_arcsec": "levelling_rms_arcsec",
            "tilt_sensor_rms_arcsec": "levelling_rms_arcsec",
            "beam_divergence_mrad": "beam_divergence_mrad",
            "beam_exit_mm": "beam_exit_mm",
            "setup_min": "setup_min",
            "reference_reflectance": "reflectance",
            "ranging_exponent": "ranging_exponent",
            "range_reflectance": "reflectance",
            "dark_range_m": "max_range_m",
            "dark_reflectance": "reflectance",
            "prealign_position_mm": "start_position_mm",
            "prealign_heading_arcsec": "start_heading_arcsec",
        }
        for name, rng in [*figures.items(), *optional.items()]:
            if name in figures or getattr(self, name) is not None:
                self._set(name, _number(getattr(self, name), f"{who}: {name}", rng))
        if self.min_range_m >= self.max_range_m:
            raise InputError(
                f"{who}: min_range_m ({self.min_range_m:g} m) must be smaller than max_range_m "
                f"({self.max_range_m:g} m)"
            )
        try:
            lo, hi = (float(v) for v in self.vertical_fov_deg)
        except (TypeError, ValueError):
            raise InputError(
                f"{who}: vertical_fov_deg must be two elevation angles (lowest, highest) in "
                f"degrees, e.g. (-45, 90); got {self.vertical_fov_deg!r}"
            ) from None
        if not (-90.0 <= lo < hi <= 90.0):
            raise InputError(
                f"{who}: vertical_fov_deg must satisfy -90 <= lowest < highest <= 90 [deg]; "
                f"got ({lo:g}, {hi:g})"
            )
        self._set("vertical_fov_deg", (lo, hi))
        if self.registration not in (None, "targets", "cloud", "hybrid"):
            raise InputError(
                f"{who}: registration must be targets, cloud or hybrid; got {self.registration!r}"
            )
        if self.prealign not in (None, "vis"):
            raise InputError(
                f"{who}: prealign must be vis (the scanner tracks its walk between set-ups) "
                f"or left out (the operator picks common points); got {self.prealign!r}"
            )
        presets = tuple(
            p if isinstance(p, Preset) else Preset(**_preset_table(p, who)) for p in self.presets
        )
        self._set("presets", presets)
        names = [p.name for p in presets]
        if len(set(names)) != len(names):
            raise InputError(f"{who}: two presets share a name ({', '.join(names)})")
        if self.default_preset is not None and self.default_preset not in names:
            raise InputError(
                f"{who}: default_preset {self.default_preset!r} is not one of its presets "
                f"({', '.join(names) or 'none'})"
            )
        if (self.dark_range_m is None) != (self.dark_reflectance is None):
            raise InputError(
                f"{who}: dark_range_m and dark_reflectance go together (the datasheet's reach "
                "on a darker surface and that surface's reflectance); give both or neither"
            )
        if self.dark_reflectance is not None and not (
            self.dark_reflectance < self.reach_reflectance and self.dark_range_m < self.max_range_m
        ):
            raise InputError(
                f"{who}: the dark reach ({self.dark_range_m:g} m at "
                f"{self.dark_reflectance:.0%}) must be shorter than max_range_m "
                f"({self.max_range_m:g} m) and on a darker surface than "
                f"{self.reach_reflectance:.0%}"
            )
        if not isinstance(self.sector_scan, bool):
            raise InputError(f"{who}: sector_scan must be true or false")
        if not self.label:
            self._set("label", self.name)

    def _set(self, name: str, value: Any) -> None:
        object.__setattr__(self, name, value)

    # -- derived figures -------------------------------------------------------------------
    @property
    def tilt_rms_arcsec(self) -> float:
        """RMS of the tilt angle ``m_ν`` [″] (the horizontal figure when none was given)."""
        v = self.vertical_angle_rms_arcsec
        return self.angle_rms_arcsec if v is None else v

    @property
    def initial_tilt_rms_arcsec(self) -> float:
        """RMS ``m_ν0`` of the initial (horizontal) direction in eq. 4 of Voroshilov &
        Karachentsev [″]: the levelling (compensator) figure of a levelled scanner, else
        ``m_ν`` as the paper's Table 2 assumes. The one place this default is decided."""
        v = self.levelling_rms_arcsec
        return self.tilt_rms_arcsec if v is None else v

    @property
    def datum_tilt_rms_arcsec(self) -> float:
        """How well the vertical of one scan is known, without a compensator [″]: its
        recorded tilt where the scanner records one (:attr:`tilt_sensor_rms_arcsec`), else
        ``m_ν0`` (:attr:`initial_tilt_rms_arcsec`) — the datum scan's lean when the
        network's vertical is the datum's
        (:func:`planner.registration_error.datum_tilt_cov`)."""
        v = self.tilt_sensor_rms_arcsec
        return self.initial_tilt_rms_arcsec if v is None or self.is_levelled else v

    @property
    def start_error(self) -> tuple[float, float, float]:
        """Where a cloud-to-cloud registration of two of its scans starts: the RMS of the
        child's position per axis [mm], of its heading and of its tilt per axis [″] relative
        to its parent. Position and heading: the pre-alignment's figures where the profile
        states them, else an operator's picking (:data:`MANUAL_START_POSITION_MM`,
        :data:`MANUAL_START_HEADING_ARCSEC`); tilt: what levels one scan
        (:attr:`datum_tilt_rms_arcsec`), for both scans."""
        pos = self.prealign_position_mm
        head = self.prealign_heading_arcsec
        return (
            MANUAL_START_POSITION_MM if pos is None else pos,
            MANUAL_START_HEADING_ARCSEC if head is None else head,
            math.sqrt(2.0) * self.datum_tilt_rms_arcsec,
        )

    @property
    def is_levelled(self) -> bool:
        """Whether a compensator levels the scanner (a ``levelling_rms_arcsec`` is given)."""
        return self.levelling_rms_arcsec is not None

    def with_levelling(self, levelling_rms_arcsec: float) -> Scanner:
        """This scanner levelled to ``levelling_rms_arcsec`` [″] per axis (a compensator's
        figure the user gives: from a test of their own instrument, or a scanner whose
        profile publishes none), said in its notes."""
        return replace(
            self,
            levelling_rms_arcsec=levelling_rms_arcsec,
            notes=f"{self.notes} Levelling {levelling_rms_arcsec:g}″ per axis given by the "
            "user.".strip(),
        )

    def preset(self, name: str | None) -> Preset | None:
        """The preset called ``name`` (None: the default preset, if any).

        Raises
        ------
        InputError
            For a name the scanner has no preset of; the message lists them.
        """
        name = self.default_preset if name is None else name
        if name is None:
            return None
        for p in self.presets:
            if p.name.lower() == str(name).strip().lower():
                return p
        raise InputError(
            f"scanner {self.name!r} has no preset {name!r}; its presets: "
            f"{', '.join(p.name for p in self.presets) or 'none (give --step-mm-at-10m)'}"
        )

    def choose_preset(self, max_step_mm_at_10m: float | None) -> Preset | None:
        """The coarsest preset whose step is at most ``max_step_mm_at_10m`` (None: the
        default preset, if any); the finest where none is fine enough; None without
        presets.

        >>> s = Scanner(name="x", range_rms_mm=1, angle_rms_arcsec=10, presets=(
        ...     Preset("low", 12.0), Preset("medium", 6.0), Preset("high", 3.0)),
        ...     default_preset="medium")
        >>> s.choose_preset(8.0).name, s.choose_preset(1.0).name, s.choose_preset(None).name
        ('medium', 'high', 'medium')
        """
        if not self.presets:
            return None
        if max_step_mm_at_10m is None:
            return self.preset(None)
        fine = [p for p in self.presets if p.step_mm_at_10m <= max_step_mm_at_10m * (1 + 1e-9)]
        if fine:
            return max(fine, key=lambda p: (p.step_mm_at_10m, p.rate_hz or math.inf))
        return min(self.presets, key=lambda p: p.step_mm_at_10m)

    def range_rms_at(self, distance_m: ArrayLike) -> np.ndarray:
        """Ranging RMS ``m_S = a + b·D`` [mm] at ``distance_m`` [m] (b in ppm = mm/km), on
        the reference surface square to the beam."""
        d = as_float_array(distance_m, "distance_m")
        return self.range_rms_mm + self.range_ppm * 1e-3 * d

    # -- the returned signal (planner.signal) ---------------------------------------------
    @property
    def ref_reflectance(self) -> float:
        """The reflectance the ranging figures hold on (the profile's, else the default)."""
        r = self.reference_reflectance
        return DEFAULT_REFERENCE_REFLECTANCE if r is None else r

    @property
    def noise_exponent(self) -> float:
        """k of ``m_S ∝ q^(−k)`` (the profile's, else the default)."""
        k = self.ranging_exponent
        return DEFAULT_RANGING_EXPONENT if k is None else k

    @property
    def reach_reflectance(self) -> float:
        """The reflectance ``max_range_m`` is stated on."""
        r = self.range_reflectance
        return self.ref_reflectance if r is None else r

    @property
    def reach_exponent(self) -> float:
        """p of ``R_max ∝ q^p``: from the two reaches the profile states, else ½."""
        if self.dark_range_m is None or self.dark_reflectance is None:
            return DEFAULT_RANGE_EXPONENT
        return reach_exponent(
            self.max_range_m, self.reach_reflectance, self.dark_range_m, self.dark_reflectance
        )

    def range_rms_on(
        self, distance_m: ArrayLike, reflectance: ArrayLike, cos_incidence: ArrayLike = 1.0
    ) -> np.ndarray:
        """Ranging RMS [mm] at ``distance_m`` on a surface of ``reflectance`` (NaN: the
        reference surface) seen at incidence θ (:func:`planner.signal.signal_ranging_rms_mm`).

        >>> sc = Scanner(name="x", range_rms_mm=1.0, angle_rms_arcsec=10)
        >>> sc.range_rms_on([10.0, 10.0], [0.8, 0.2]).tolist()
        [1.0, 2.0]
        """
        q = relative_signal(reflectance, cos_incidence, self.ref_reflectance)
        return signal_ranging_rms_mm(self.range_rms_at(distance_m), q, self.noise_exponent)

    def max_range_on(self, reflectance: ArrayLike, cos_incidence: ArrayLike = 1.0) -> np.ndarray:
        """The reach [m] on a surface of ``reflectance`` (NaN: the reference surface) seen at
        incidence θ (:func:`planner.signal.signal_reach_m`), never beyond ``max_range_m``.

        >>> sc = Scanner(name="x", range_rms_mm=1.0, angle_rms_arcsec=10, max_range_m=120.0)
        >>> sc.max_range_on([0.8, 0.2, float("nan")]).tolist()
        [120.0, 60.0, 120.0]
        """
        rho = np.asarray(reflectance, dtype=float)
        rho = np.where(np.isnan(rho), self.ref_reflectance, rho)  # NaN: the reference surface
        q = relative_signal(rho, cos_incidence, self.reach_reflectance)
        return np.asarray(signal_reach_m(self.max_range_m, q, self.reach_exponent), dtype=float)

    # -- construction ---------------------------------------------------------------------
    @classmethod
    def from_name(cls, name: str) -> Scanner:
        """The profile called ``name`` (case-insensitive): shipped, or installed by the user
        in :func:`user_profile_dir` (``planner calibrate … --install``).

        Raises
        ------
        InputError
            For an unknown name; the message lists the valid names.
        """
        cat = {**catalogue(), **user_profiles()[0]}
        key = str(name).strip().lower()
        if key in cat:
            return cat[key]
        close = difflib.get_close_matches(key, list(cat), n=1)
        hint = f" Did you mean {close[0]!r}?" if close else ""
        raise InputError(
            f"Unknown scanner {name!r}.{hint} Valid names: {', '.join(cat)}. "
            "For your own instrument pass a profile file (.toml) or build Scanner(...) in code."
        )

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> Scanner:
        """Build a profile from a mapping (e.g. one ``[[scanner]]`` table of a TOML file).

        A key that is neither a field nor a known record (``calibration``) is refused, with
        the field it most likely meant; records are kept in ``extra`` (so a calibration
        survives a round trip).
        """
        if not isinstance(data, Mapping):
            raise InputError(
                f"a scanner profile must be a table of key = value pairs; got a "
                f"{type(data).__name__}"
            )
        known = {f.name for f in fields(cls)} - {"extra"}
        unknown = [k for k in data if k not in known and k not in RECORD_KEYS]
        if unknown:
            who = data.get("name", "<unnamed>")
            hints = []
            for k in unknown:
                close = difflib.get_close_matches(str(k), sorted(known), n=1)
                hints.append(f"{k!r}" + (f" (did you mean {close[0]!r}?)" if close else ""))
            raise InputError(
                f"scanner profile {who!r} has unknown key(s) {', '.join(hints)}; the keys are "
                f"{', '.join(sorted(known))}"
            )
        kwargs = {k: v for k, v in data.items() if k in known}
        extra = {k: v for k, v in data.items() if k not in known}
        missing = [k for k in ("name", "range_rms_mm", "angle_rms_arcsec") if k not in kwargs]
        if missing:
            raise InputError(
                f"Scanner profile {data.get('name', '<unnamed>')!r} lacks {', '.join(missing)}; "
                "a profile needs at least name, range_rms_mm and angle_rms_arcsec"
            )
        if "vertical_fov_deg" in kwargs:
            kwargs["vertical_fov_deg"] = tuple(kwargs["vertical_fov_deg"])
        if "preset" in extra:  # [[scanner.preset]] tables
            kwargs["presets"] = tuple(extra.pop("preset"))
        return cls(**kwargs, extra=extra)

    @classmethod
    def from_file(cls, path: str | Path, name: str | None = None) -> Scanner:
        """Read a profile from a TOML file in the catalogue's format.

        A file with several ``[[scanner]]`` tables needs ``name`` to pick one.
        """
        scanners = read_scanner_file(path)
        if name is None:
            if len(scanners) == 1:
                return scanners[0]
            raise InputError(
                f"{path} holds {len(scanners)} scanner profiles "
                f"({', '.join(s.name for s in scanners)}); say which one with name=..."
            )
        for s in scanners:
            if s.name == name:
                return s
        raise InputError(
            f"{path} has no scanner {name!r}; it has {', '.join(s.name for s in scanners)}"
        )

    # -- output ---------------------------------------------------------------------------
    def to_dict(self) -> dict[str, Any]:
        """Plain mapping of every set field (None left out), ``extra`` merged in; the
        presets as the ``preset`` list of tables, as the file has them."""
        d = asdict(self)
        extra = d.pop("extra")
        d["vertical_fov_deg"] = list(self.vertical_fov_deg)
        presets = d.pop("presets")
        if presets:
            d["preset"] = [{k: v for k, v in p.items() if v is not None} for p in presets]
        d = {k: v for k, v in d.items() if v is not None}
        d.update(extra)
        return d

    def to_toml(self) -> str:
        """This profile as one ``[[scanner]]`` table of the catalogue's TOML format."""
        lines = ["[[scanner]]"]
        for key, value in self.to_dict().items():
            lines.append(f"{key} = {_toml_value(value)}")
        return "\n".join(lines) + "\n"

    def profile_file_text(self) -> str:
        """The text of this profile's own file (a header saying the units, then the table)."""
        return _TOML_HEADER + "\n" + self.to_toml()

    def save(self, path: str | Path) -> Path:
        """Write this profile as a TOML file (atomically: a good file is never half-replaced)."""
        return write_text_atomic(path, self.profile_file_text())


_TOML_HEADER = "# tls-planner scanner profile (units: mm, ppm, arc-seconds, m, deg)\n"

#: Tables a profile may carry besides its fields: records kept with it (a calibration, the
#: datasheet's accuracy figures) and its ``[[scanner.preset]]`` tables (read into
#: :attr:`Scanner.presets`).
RECORD_KEYS = ("calibration", "datasheet_3d_accuracy_mm", "preset")


def _preset_table(table: Any, who: str) -> dict[str, Any]:
    """A ``[[scanner.preset]]`` table checked for its keys."""
    keys = {f.name for f in fields(Preset)}
    if not isinstance(table, Mapping) or "name" not in table or "step_mm_at_10m" not in table:
        raise InputError(
            f"{who}: a preset is a table with at least name and step_mm_at_10m; got {table!r}"
        )
    unknown = sorted(set(table) - keys)
    if unknown:
        raise InputError(
            f"{who}: preset {table.get('name')!r} has unknown key(s) {', '.join(unknown)}; "
            f"the keys are {', '.join(sorted(keys))}"
        )
    return dict(table)


#: A profile name: lower-case letters, digits, '.', '_' and '-' (it becomes a file name).
_NAME = re.compile(r"[a-z0-9][a-z0-9._-]{0,63}")


def check_profile_name(name: str) -> str:
    """``name`` if it can name a profile (and its file), else an InputError saying why."""
    key = str(name).strip().lower()
    if not _NAME.fullmatch(key) or ".." in key:
        raise InputError(
            f"{name!r} cannot name a scanner profile: use 1–64 lower-case letters, digits, "
            "'.', '_' or '-', starting with a letter or digit (e.g. my-p20)"
        )
    return key


def _number(value: Any, what: str, rng: str) -> float:
    """A profile's figure checked against its physical range (:data:`planner.ranges.RANGES`)."""
    return check_number(value, what, RANGES[rng])


def _toml_value(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int | float):
        return repr(float(value))
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)
    if isinstance(value, list | tuple):
        return "[" + ", ".join(_toml_value(v) for v in value) + "]"
    if isinstance(value, Mapping):
        return "{ " + ", ".join(f"{k} = {_toml_value(v)}" for k, v in value.items()) + " }"
    raise InputError(f"cannot write {value!r} into a scanner profile (numbers, text, lists only)")


def _parse_toml(text: str, origin: str) -> list[Scanner]:
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(
            f"{origin} is not valid TOML ({exc}); see planner/data/scanners.toml"
        ) from None
    except RecursionError:
        raise InputError(
            f"{origin} nests its arrays or tables too deeply to be a scanner profile (a "
            "profile is [[scanner]] tables of key = value pairs)"
        ) from None
    tables = data.get("scanner")
    if tables is None and "name" in data:
        tables = [data]  # a single profile written without the [[scanner]] header
    if not tables or not isinstance(tables, list) or not all(isinstance(t, dict) for t in tables):
        raise InputError(
            f"{origin} holds no [[scanner]] tables (a scanner profile is one or more "
            "[[scanner]] tables of key = value pairs; see planner/data/scanners.toml)"
        )
    return [Scanner.from_dict(t) for t in tables]


def read_scanner_file(path: str | Path) -> list[Scanner]:
    """Every profile in a scanner TOML file."""
    p = user_file(path, "scanner profile file")
    try:
        text = p.read_text(encoding="utf-8")
    except UnicodeDecodeError:
        raise InputError(f"{p} is not a UTF-8 text file; a scanner profile is TOML text") from None
    return _parse_toml(text, str(p))


def user_profile_dir() -> Path:
    """Where a user's own profiles live: ``$TLS_PLANNER_PROFILES``, else
    ``~/.tls-planner/scanners``. Every ``*.toml`` there is found by name."""
    env = os.environ.get("TLS_PLANNER_PROFILES")
    return Path(env).expanduser() if env else Path.home() / ".tls-planner" / "scanners"


def installed_profile_path(name: str) -> Path:
    """Where the profile ``name`` is installed (:func:`user_profile_dir`), after checking the
    name can be installed: a valid profile name, and not a catalogue scanner's (those names
    are reserved, so a catalogue name always means the shipped figures)."""
    key = check_profile_name(name)
    if key in catalogue():
        raise InputError(
            f"{key!r} is a catalogue scanner's name, and catalogue names are reserved; "
            "install your profile under another name (e.g. my-" + key + ")"
        )
    return user_profile_dir() / f"{key}.toml"


def user_profiles() -> tuple[dict[str, Scanner], list[str]]:
    """The profiles installed in :func:`user_profile_dir`, and warnings about the files that
    were skipped: unreadable ones, and ones taking a catalogue name (catalogue names are
    reserved, so ``--scanner leica-p20-lab`` always means the shipped figures)."""
    folder = user_profile_dir()
    out: dict[str, Scanner] = {}
    warnings: list[str] = []
    if not folder.is_dir():
        return out, warnings
    reserved = set(catalogue())
    for path in sorted(folder.glob("*.toml")):
        try:
            scanners = read_scanner_file(path)
        except InputError as exc:
            warnings.append(f"skipped the profile file {path}: {exc}")
            continue
        for s in scanners:
            key = s.name.lower()
            if key in reserved:
                warnings.append(
                    f"skipped the profile {s.name!r} in {path}: the name is the catalogue's; "
                    "rename your profile (name = ...) to use it"
                )
            elif key in out:
                warnings.append(f"skipped a second profile {s.name!r} in {path}")
            else:
                out[key] = s
    return out, warnings


@cache
def catalogue() -> dict[str, Scanner]:
    """The shipped profiles by name, in file order."""
    text = resources.files("planner.data").joinpath("scanners.toml").read_text(encoding="utf-8")
    return {s.name: s for s in _parse_toml(text, "planner/data/scanners.toml")}


def load_scanner(spec: Scanner | str | Path) -> Scanner:
    """A Scanner from a Scanner, a catalogue name, or the path of a profile file."""
    if isinstance(spec, Scanner):
        return spec
    text = str(spec)
    if isinstance(spec, Path) or text.endswith(".toml") or Path(text).is_file():
        return Scanner.from_file(text)
    return Scanner.from_name(text)
