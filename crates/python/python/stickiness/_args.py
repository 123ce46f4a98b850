"""Argument handling shared by the public functions: numbers and arrays, astropy quantities,
broadcasting, the material, the geometry, T_vis, the method, and the warnings.

Every public function converts its arguments here and then calls the compiled core; nothing
here computes physics.
"""

from __future__ import annotations

import math
import sys
import warnings
from typing import Any, Dict, Iterator, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import _core
from ._core import Material

#: A number or an array of numbers (anything ``numpy.asarray`` turns into real numbers), or an
#: ``astropy.units.Quantity`` of the argument's dimension.
ArrayLike = Union[float, int, Sequence[float], np.ndarray]
#: A Python float for scalar inputs, an ndarray of the broadcast shape for array inputs.
FloatOrArray = Union[float, np.ndarray]

#: The SI unit of each dimensional argument, as astropy spells it; a Quantity is converted to it.
UNITS: Dict[str, str] = {
    "radius": "m",
    "radius2": "m",
    "monomer_radius": "m",
    "t_vis": "s",
    "t_end": "s",
    "v_in": "m/s",
    "v_in_err": "m/s",
    "v_stick": "m/s",
    "v_stick_err": "m/s",
    "v_max": "m/s",
    "v_frag_refractory": "m/s",
    "gamma_sv": "J/m2",
    "young": "Pa",
    "density": "kg/m3",
    "T": "K",
    "t_h2o": "K",
    "t_co2": "K",
    "width": "K",
    "median": "m",
}

#: The methods of the threshold functions, and their codes in the core's ``"method"`` column.
METHODS = ("search", "table")


class StickinessWarning(UserWarning):
    """Valid input for which the model's results should be read with care.

    Issued for a Tabor parameter below 1 (JKR theory, on which the model stands, is outside
    its validity; Section 2.2), a radius outside 10 nm - 1 cm (likely a unit slip), impact
    speeds above 1 km/s, and fits whose range reaches V_stick,JKR or the search limit.
    """



def shown(value: Any) -> str:
    """``value`` as an error message shows it: a numpy scalar as the Python number it holds
    (``-2e-05``, not ``np.float64(-2e-05)``), anything else as its ``repr``."""
    if isinstance(value, np.generic):
        value = value.item()
    return repr(value)

def is_quantity(value: Any) -> bool:
    """Whether ``value`` is an ``astropy.units.Quantity`` (without importing astropy)."""
    units = sys.modules.get("astropy.units")
    return units is not None and isinstance(value, units.Quantity)


def si(name: str, value: Any) -> Any:
    """``value`` in SI units: a Quantity is converted to the unit of ``name`` (``UNITS``), or
    to a plain number where ``name`` is dimensionless (``k``: ``1 * u.percent`` is 0.01); a
    wrong dimension raises ``ValueError`` naming the argument and the expected unit. Other
    values are returned as they are."""
    if not is_quantity(value):
        return value
    unit = UNITS.get(name)
    if unit is None:
        try:
            return value.to_value("")
        except Exception:  # astropy.units.UnitConversionError
            raise ValueError(
                f"{name}: expected a dimensionless number, got a quantity in {value.unit}"
            ) from None
    try:
        return value.to_value(unit)
    except Exception:  # astropy.units.UnitConversionError (and unit parsing errors)
        got = str(value.unit) or "a dimensionless number"  # astropy writes that unit as ""
        raise ValueError(
            f"{name}: expected a quantity in {unit} (or convertible to it), got {got}"
        ) from None


#: Python number types taken as they are (the common case, checked first: no numpy call).
_NUMBERS = (float, int)


def float_array(name: str, value: Any) -> np.ndarray:
    """``value`` as a float64 array (SI); ``TypeError`` naming ``name`` for anything that is not
    real numbers."""
    kind = type(value)
    if kind is float or (kind is int):
        return np.array(value, dtype=np.float64)
    if kind is np.ndarray and value.dtype == np.float64:
        return value
    value = si(name, value)
    if isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name}: expected a number or an array of numbers, got a bool")
    if value is None:
        raise TypeError(f"{name}: expected a number or an array of numbers, got None")
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            a = np.asarray(value)
    except Exception as e:  # ragged lists and the like
        raise TypeError(f"{name}: expected a number or an array of numbers ({e})") from None
    if a.dtype.kind not in "iuf":
        what = {"U": "text", "S": "bytes", "b": "booleans", "c": "complex numbers",
                "O": "objects", "M": "dates", "m": "time spans"}.get(a.dtype.kind, str(a.dtype))
        raise TypeError(f"{name}: expected real numbers, got {what} ({value!r:.60})")
    return a.astype(np.float64, copy=False)


def scalar(name: str, value: Any) -> float:
    """One number (SI); ``TypeError`` naming ``name`` for an array or a non-number."""
    if type(value) is float:
        return value
    a = float_array(name, value)
    if a.ndim != 0:
        raise TypeError(f"{name}: expected one number, got an array of shape {a.shape}")
    return float(a)


def scalar_option(name: str, value: Any) -> Optional[float]:
    """``None`` or one number (SI)."""
    return None if value is None else scalar(name, value)


def flag(name: str, value: Any) -> bool:
    """A bool; ``TypeError`` naming ``name`` for anything else."""
    if value is False or value is True:
        return value
    if not isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name}: expected a bool, got {type(value).__name__}")
    return bool(value)


def material(value: Any) -> Material:
    """A :class:`Material`; a string is a preset name (``"co2"``) or a JSON file's path."""
    if isinstance(value, Material):
        return value
    if isinstance(value, str):
        try:
            return Material.named(value)
        except OSError as e:  # a path that is no material file
            raise ValueError(f"material = {value!r}: {e}") from None
    raise TypeError(
        f"material: expected a stickiness.Material or a preset name, got {type(value).__name__}"
    )


def geometry(radius2: Any, wall: Any) -> bool:
    """Checks the second body: ``radius2`` or ``wall``, not both. Returns ``wall``."""
    wall = flag("wall", wall)
    if wall and radius2 is not None:
        raise ValueError("radius2 and wall=True exclude each other (a wall is R2 -> infinity)")
    return wall


def method(value: Any) -> str:
    """``"search"`` or ``"table"``."""
    if type(value) is str and value in METHODS:  # spelt as they are (no lower() to call)
        return value
    return choice("method", value, METHODS)


def choice(name: str, value: Any, names: Sequence[str]) -> str:
    """``value`` among ``names`` in any case, lowered; ``TypeError`` for what is no string,
    ``ValueError`` for another string, each naming ``name`` and the choices."""
    allowed = " or ".join(repr(n) for n in names)
    if not isinstance(value, str):
        raise TypeError(f"{name} = {value!r}: must be a string, {allowed}")
    if value.lower() not in names:
        raise ValueError(f"{name} = {value!r}: must be {allowed}")
    return value.lower()


def keyed(
    name: str, value: Any, form: str, keys: Sequence[str], unknown: str
) -> Iterator[Tuple[str, Any]]:
    """The items of ``value``, a dict of the ``form`` (None: none) whose keys are among ``keys``;
    ``ValueError`` naming ``name`` for anything else (``unknown``, with ``{key}`` and ``{keys}``
    filled in, for a key not among them), ``TypeError`` for what is no dict."""
    if value is None:
        return
    if not isinstance(value, dict):
        raise TypeError(f"{name}: expected a dict {form}, got {type(value).__name__}")
    for key, item in value.items():
        if key not in keys:
            raise ValueError(f"{name}: " + unknown.format(key=key, keys=tuple(keys)))
        yield key, item


def law_name(name: str, value: Any, required: bool = False) -> Optional[str]:
    """``None`` (unless ``required``) or a size law's name (``'co2'``, ``'h2o'``)."""
    if value is None and not required:
        return None
    return choice(name, value, ("co2", "h2o"))


def t_vis_or_law(value: Any, law: Any, required: bool) -> None:
    """Refuses ``t_vis`` and ``t_vis_law`` both given (``ValueError``), and neither where one is
    ``required`` (``TypeError``, as Python names a missing argument)."""
    if value is not None and law is not None:
        raise ValueError("give t_vis or t_vis_law, not both")
    if required and value is None and law is None:
        raise TypeError("missing argument: t_vis (s) or t_vis_law ('co2' or 'h2o')")


def t_vis(
    value: Any, law: Optional[str], radius: Any, default: Optional[float], of: Any = None
) -> Any:
    """T_vis as given, from the size law ``law`` at ``radius``, or ``default`` (None: required).
    A law of one ice with the material ``of`` holding the other ice's constants is warned of
    (``StickinessWarning``, at the public function's caller)."""
    law = law_name("t_vis_law", law)
    t_vis_or_law(value, law, default is None)
    if law is not None:
        caution = None if of is None else _core.t_vis_law_mismatch(law, material(of))
        if caution is not None:
            warnings.warn(caution, StickinessWarning, stacklevel=3)
        b = Broadcast(radius=radius)
        return b.out(b.call(_core.t_vis_law, law, b.flat["radius"]))
    return default if value is None else value


#: The names of result codes as numpy arrays, made once ("search"/"table", "ode"/"table"):
#: an array of strings made at every call cost as much as the rest of a 64-element result.
_NAME_ARRAYS: Dict[Tuple[str, ...], np.ndarray] = {}

#: The number arguments that may be None (absent) in a broadcast.
OPTIONAL = ("radius2",)


class Broadcast:
    """Number arguments broadcast together and flattened for the compiled core."""

    def __init__(self, **args: Any) -> None:
        floats: Dict[str, Any] = {}
        for k, v in args.items():
            if type(v) is float:
                floats[k] = v
            elif v is not None or k not in OPTIONAL:
                break
        else:
            # the common scalar call (floats only): the floats themselves, which the core
            # takes as one element each and answers with floats; nothing to check or broadcast
            # (two thirds of a scalar call's overhead otherwise; a plain loop, no generator)
            self.shapes: Dict[str, Tuple[int, ...]] = dict.fromkeys(floats, ())
            self.shape: Tuple[int, ...] = ()
            self.flat: Dict[str, Any] = floats
            self.scalar = True
            return
        if self._one_vector(args):
            return
        arrays: Dict[str, np.ndarray] = {}
        for k, v in args.items():
            if v is None:
                if k not in OPTIONAL:
                    raise TypeError(f"{k}: expected a number or an array of numbers, got None")
                continue
            arrays[k] = float_array(k, v)
        self.shapes = {k: a.shape for k, a in arrays.items()}
        distinct = set(self.shapes.values())
        shaped = distinct - {()}
        if len(shaped) <= 1:
            # one shape (all scalars, or arrays alike) besides scalars: the scalars filled to
            # its size, nothing else to broadcast (np.broadcast_shapes and broadcast_to cost
            # more than an array of 64 answers from the tables)
            self.shape = shaped.pop() if shaped else ()
            size = math.prod(self.shape)
            self.flat = {
                k: (np.ascontiguousarray(a).reshape(-1) if a.shape or not self.shape
                    else np.full(size, a[()]))
                for k, a in arrays.items()
            }
        else:
            try:
                self.shape = np.broadcast_shapes(*distinct)
            except ValueError:
                shapes = ", ".join(f"{k} {s}" for k, s in self.shapes.items())
                raise ValueError(f"the arguments cannot be broadcast together: {shapes}") from None
            self.flat = {
                k: (a.reshape(-1) if a.shape == self.shape
                    else np.broadcast_to(a, self.shape).reshape(-1))
                for k, a in arrays.items()
            }
            self.flat = {k: np.ascontiguousarray(a) for k, a in self.flat.items()}
        self.scalar = not self.shape and all(not s for s in self.shapes.values())

    def _one_vector(self, args: Dict[str, Any]) -> bool:
        """The common array call: floats and flat contiguous float64 arrays of one length (a
        sweep over T_vis at one radius, a sampler's walkers): taken as they are, the floats
        filled to that length; ``False`` (nothing set) for anything else."""
        shape = None
        for k, v in args.items():
            kind = type(v)
            if kind is np.ndarray:
                # flat, float64 and contiguous: one stride of 8 bytes (no flags object)
                if v.dtype != np.float64 or v.strides != (8,) or (
                        shape is not None and v.shape != shape):
                    return False
                shape = v.shape
            elif not (kind is float or (v is None and k in OPTIONAL)):
                return False
        if shape is None:
            return False
        self.shapes = {}
        self.flat = {}
        for k, v in args.items():
            if type(v) is np.ndarray:
                self.shapes[k] = shape
                self.flat[k] = v
            elif v is not None:
                self.shapes[k] = ()
                # empty + fill: a third less than np.full
                filled = np.empty(shape)
                filled.fill(v)
                self.flat[k] = filled
        self.shape = shape
        self.scalar = False
        return True

    @property
    def size(self) -> int:
        return math.prod(self.shape)

    def out(self, flat: Any) -> Any:
        """A flat result as a Python scalar (scalar inputs) or an array of the broadcast shape."""
        if self.scalar:
            kind = type(flat)
            return flat if kind is float else flat.item(0) if kind is np.ndarray else flat[0]
        if type(flat) is np.ndarray and flat.shape == self.shape:
            return flat
        return np.asarray(flat).reshape(self.shape)

    def methods(self, codes: Any) -> Any:
        """The core's method codes as ``'search'``/``'table'``: a string, or an array of them."""
        return self.names(METHODS, codes)

    def names(self, names: Sequence[str], codes: Any) -> Any:
        """Codes (indices into ``names``) as a string, or an array of them."""
        if self.scalar:
            return names[codes if type(codes) is int else int(codes[0])]
        table = _NAME_ARRAYS.get(tuple(names))
        if table is None:
            table = _NAME_ARRAYS.setdefault(tuple(names), np.array(names))
        return table.take(codes).reshape(self.shape)

    def name_at(self, field: str, flat: int) -> str:
        """``field`` with the index, in its own shape, of element ``flat`` of the broadcast."""
        shape = self.shapes.get(field, ())
        if not shape or not self.shape:
            return field
        full = np.unravel_index(flat, self.shape)
        offset = len(self.shape) - len(shape)
        own = [0 if shape[j] == 1 else int(full[offset + j]) for j in range(len(shape))]
        return f"{field}[{', '.join(map(str, own))}]"

    def call(self, fn: Any, *args: Any) -> Any:
        """Calls the core, turning its bad-input errors into ``ValueError`` naming the element."""
        try:
            return fn(*args)
        except _core._InputError as e:
            raise ValueError(self.name_at(e.field, e.index) + e.rest) from None

    def warn(self, found: List[Tuple[int, str, str]], stacklevel: int = 4) -> None:
        """One ``StickinessWarning`` per kind of warning found, naming the first element.

        ``stacklevel`` 4: ``warnings.warn`` <- here <- the public function's helper <- the public
        function <- the user's line; a public function that calls ``warn`` itself passes 3.
        """
        kinds: Dict[str, List[Tuple[int, str]]] = {}
        for index, kind, text in found:
            kinds.setdefault(kind, []).append((index, text))
        for items in kinds.values():
            index, text = items[0]
            if not self.scalar:
                where = np.unravel_index(index, self.shape) if self.shape else ()
                text += (
                    f" [first at element {tuple(int(i) for i in where)}; "
                    f"{len(items)} of {self.size} elements]"
                )
            warnings.warn(text, StickinessWarning, stacklevel=stacklevel)
