//! The conversions shared by the vectorised functions of `stickiness._core`, written once:
//! flat `float64` arrays of one length in (the package broadcasts them), the material, bodies
//! and crack law of each element ([`Elements`]), the warnings as `(index, kind, message)`, and
//! a dict of flat arrays out (NaN where a value does not exist). The settings are those of the
//! CLI, so the numbers are bit-identical to its `--json` output.

use crate::error::Error;
use crate::material::Material;
use crate::parallel::{Columns, Row};
use numpy::{PyArray1, PyReadonlyArray1};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::collections::HashMap;
use thresholds::{
    Contact, CrackLaw, Geometry, GreenwoodError, OutOfRange, SearchOptions, ThresholdMethod,
    Warning,
};

/// A flat number argument: a contiguous float64 array, or one Python float. A call whose
/// arguments are all floats (the package's scalar calls) makes no array on either side: its
/// [`columns`] are floats too, which saves a scalar call a third of its cost.
pub enum Array<'py> {
    /// One Python float: an array of one element.
    One(f64),
    /// A flat float64 array.
    Many(PyReadonlyArray1<'py, f64>),
}

impl<'a, 'py> FromPyObject<'a, 'py> for Array<'py> {
    type Error = PyErr;

    fn extract(obj: pyo3::Borrowed<'a, 'py, PyAny>) -> PyResult<Self> {
        // exactly a float: a 1-element array also converts to float, and must stay an array
        if let Ok(f) = obj.cast_exact::<pyo3::types::PyFloat>() {
            return Ok(Self::One(f.value()));
        }
        Ok(Self::Many(obj.extract()?))
    }
}

impl Array<'_> {
    /// Whether this is one float (not an array).
    pub fn is_one(&self) -> bool {
        matches!(self, Self::One(_))
    }
}

/// The contiguous data of a flat array argument (one element for a float).
pub fn data<'a>(a: &'a Array<'_>, name: &str) -> PyResult<&'a [f64]> {
    match a {
        Array::One(x) => Ok(std::slice::from_ref(x)),
        Array::Many(a) => a.as_slice().map_err(|_| {
            PyValueError::new_err(format!("{name}: expected a contiguous float64 array"))
        }),
    }
}

/// The common length of the flat arguments (the package broadcasts them first).
pub fn common_len(lens: &[(&str, usize)]) -> PyResult<usize> {
    let n = lens.first().map_or(0, |l| l.1);
    match lens.iter().find(|l| l.1 != n) {
        Some((name, len)) => Err(PyValueError::new_err(format!(
            "{name}: length {len} differs from {n} (the arguments must be broadcast to one shape)"
        ))),
        None => Ok(n),
    }
}

/// What every elementwise function takes: the material (with `gamma_sv` per element, if
/// given), the bodies (`radius`, optional `radius2`, `wall`), k, and its own arrays, all of one
/// length (the package broadcasts them): checked once here, then element `i`'s contact and
/// crack law.
pub struct Elements<'a> {
    material: &'a Material,
    gamma_sv: Option<&'a [f64]>,
    /// R1 of each element (m).
    pub radius: &'a [f64],
    radius2: Option<&'a [f64]>,
    wall: bool,
    /// k of each element (empty where the function takes none).
    pub k: &'a [f64],
    laws: Laws,
    /// The common length.
    pub n: usize,
    /// Whether every argument was one float: the result is then a dict of floats.
    pub scalar: bool,
}

impl<'a> Elements<'a> {
    /// The elements of a call; `own` are the function's other arrays, by name, for the length
    /// check, and `own_scalar` whether each of them was one float.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        material: &'a Material,
        gamma_sv: Option<&'a Array<'_>>,
        radius: &'a Array<'_>,
        radius2: Option<&'a Array<'_>>,
        wall: bool,
        k: Option<&'a Array<'_>>,
        own: &[(&str, &'a [f64])],
        own_scalar: bool,
    ) -> PyResult<Self> {
        let scalar = own_scalar
            && radius.is_one()
            && [radius2, gamma_sv, k].iter().flatten().all(|a| a.is_one());
        let radius = data(radius, "radius")?;
        let radius2 = radius2.map(|r| data(r, "radius2")).transpose()?;
        let gamma_sv = gamma_sv.map(|g| data(g, "gamma_sv")).transpose()?;
        let k = k.map(|k| data(k, "k")).transpose()?.unwrap_or(&[]);
        let mut lens = vec![("radius", radius.len())];
        lens.extend(radius2.map(|r| ("radius2", r.len())));
        lens.extend(gamma_sv.map(|g| ("gamma_sv", g.len())));
        if !k.is_empty() {
            lens.push(("k", k.len()));
        }
        lens.extend(own.iter().map(|(name, a)| (*name, a.len())));
        let n = common_len(&lens)?;
        Ok(Self {
            material,
            gamma_sv,
            radius,
            radius2,
            wall,
            k,
            laws: Laws::new(k),
            n,
            scalar,
        })
    }

    /// The geometry of element `i`.
    pub fn geometry(&self, i: usize) -> Geometry {
        let r1 = self.radius[i];
        match (self.wall, self.radius2) {
            (true, _) => Geometry::wall(r1),
            (false, Some(r2)) => Geometry::spheres(r1, r2[i]),
            (false, None) => Geometry::identical(r1),
        }
    }

    /// The contact of element `i` (its gamma_sv, if given per element) and whether it has
    /// warnings ([`Contact::warnings`]); the last one made on this thread is reused when element
    /// `i` has the same inputs (a scalar radius broadcast over T_vis, a sampler's walkers at one
    /// radius): a contact costs a third of a table answer, asking for its warnings a twentieth.
    pub fn contact(&self, i: usize) -> Result<(Contact, bool), Error> {
        let mut m = self.material.inner();
        if let Some(g) = self.gamma_sv {
            m.gamma_sv = g[i];
        }
        let g = self.geometry(i);
        let last = LAST_CONTACT.with_borrow(|last| match last {
            Some((pm, pg, pc, warns)) if *pm == m && *pg == g => Some((*pc, *warns)),
            _ => None,
        });
        if let Some(found) = last {
            return Ok(found);
        }
        let c = Contact::new(m, g).map_err(|e| Error::from_contact(e, i))?;
        let warns = c.has_warnings();
        LAST_CONTACT.with_borrow_mut(|last| *last = Some((m, g, c, warns)));
        Ok((c, warns))
    }

    /// The crack law of element `i`'s k; a k outside the collisions' range is refused with that
    /// range ([`thresholds::collision_k`]), not the crack law's wider 0 < k < 1.
    pub fn law(&self, i: usize) -> Result<&CrackLaw, Error> {
        let k = thresholds::collision_k(self.k[i]).map_err(|bad| Error::Input { bad, index: i })?;
        self.laws.get(k, i)
    }

    /// `f(i, contact of i)` of every element on all cores ([`crate::parallel::map`]), each with
    /// the contact's warnings followed by those `f` gives.
    pub fn map<T: Send>(
        &self,
        py: Python<'_>,
        f: impl Fn(usize, &Contact) -> Result<(T, Warned), Error> + Sync + Send,
    ) -> PyResult<Vec<(T, Warned)>> {
        crate::parallel::map(py, self.n, self.with_contact(f))
    }

    /// [`Elements::map`] for rows of floats (and a method code), written straight into their
    /// columns ([`crate::parallel::map_rows`]).
    pub fn map_rows<const N: usize>(
        &self,
        py: Python<'_>,
        f: impl Fn(usize, &Contact) -> Result<Row<N>, Error> + Sync + Send,
    ) -> PyResult<Columns> {
        crate::parallel::map_rows(py, self.n, self.with_contact(f))
    }

    /// `f` of element i with i's contact, the contact's warnings before those `f` gives.
    fn with_contact<'s, T>(
        &'s self,
        f: impl Fn(usize, &Contact) -> Result<(T, Warned), Error> + Sync + Send + 's,
    ) -> impl Fn(usize) -> Result<(T, Warned), Error> + Sync + Send + 's {
        move |i| {
            let (c, warns) = self.contact(i)?;
            let (value, own) = f(i, &c)?;
            if !warns {
                return Ok((value, own));
            }
            let mut all = warned(i, c.warnings());
            all.extend(own);
            Ok((value, all))
        }
    }
}

/// A contact with its material, geometry and whether it has warnings.
type LastContact = (thresholds::Material, Geometry, Contact, bool);

thread_local! {
    /// The last contact made on this thread, with its material and geometry: compared in place
    /// (a `RefCell`, not a `Cell` whose `get` copies the 200 bytes out first: 3-5 % of a
    /// million table answers at distinct radii, where every element misses).
    static LAST_CONTACT: std::cell::RefCell<Option<LastContact>> =
        const { std::cell::RefCell::new(None) };
}

/// One `CrackLaw` per distinct k (each table takes 0.09-0.2 ms to build and is shared), and that of
/// the first element's k apart: most calls have one k, and comparing its bits is cheaper than
/// hashing them for every element.
pub struct Laws {
    by_bits: HashMap<u64, Result<CrackLaw, OutOfRange>>,
    first: Option<(u64, Result<CrackLaw, OutOfRange>)>,
}

/// Crack laws kept across calls: a call of a few elements (a sampler's step asks V_stick of 8
/// walkers thousands of times) would otherwise spend 0.2 ms building its law, 100 times the
/// table's answers. At most this many k are kept (then the cache starts afresh), so calls
/// with random k cannot grow it without bound; a law's tables are a few hundred kB.
const CACHED_LAWS: usize = 16;

/// The process-wide cache of [`CACHED_LAWS`] crack laws, by the bits of k.
static LAW_CACHE: std::sync::Mutex<Option<HashMap<u64, CrackLaw>>> = std::sync::Mutex::new(None);

/// The crack law of `k`, from the cache or built (and then cached).
fn law(k: f64) -> Result<CrackLaw, OutOfRange> {
    let key = k.to_bits();
    if let Some(law) = LAW_CACHE
        .lock()
        .ok()
        .and_then(|c| c.as_ref().and_then(|m| m.get(&key).cloned()))
    {
        return Ok(law);
    }
    let law = CrackLaw::new(k).map_err(|e| match e {
        GreenwoodError::OutOfRange(bad) => bad,
    })?;
    if let Ok(mut cache) = LAW_CACHE.lock() {
        let map = cache.get_or_insert_with(HashMap::new);
        if map.len() >= CACHED_LAWS {
            map.clear();
        }
        map.insert(key, law.clone());
    }
    Ok(law)
}

impl Laws {
    pub fn new(k: &[f64]) -> Self {
        let mut by_bits = HashMap::new();
        let mut last = None;
        for &x in k {
            // runs of one k (the common case: a scalar k broadcast) are hashed once
            if last != Some(x.to_bits()) {
                last = Some(x.to_bits());
                by_bits.entry(x.to_bits()).or_insert_with(|| law(x));
            }
        }
        let first = k.first().and_then(|x| {
            let bits = x.to_bits();
            Some((bits, by_bits.get(&bits)?.clone()))
        });
        Self { by_bits, first }
    }

    pub fn get(&self, k: f64, i: usize) -> Result<&CrackLaw, Error> {
        let bits = k.to_bits();
        let found = match &self.first {
            Some((b, law)) if *b == bits => Some(law),
            _ => self.by_bits.get(&bits),
        };
        match found {
            Some(Ok(law)) => Ok(law),
            Some(Err(bad)) => Err(Error::Input {
                bad: bad.clone(),
                index: i,
            }),
            // every k of the call was tabulated in `new`
            None => Err(Error::Input {
                bad: OutOfRange::new("k", k, "0 < k < 1", "dimensionless"),
                index: i,
            }),
        }
    }
}

/// `(index, kind, message)` of each warning of element `i`.
pub type Warned = Vec<(usize, &'static str, String)>;

pub fn warned(i: usize, warnings: impl IntoIterator<Item = Warning>) -> Warned {
    warnings
        .into_iter()
        .map(|w| {
            let kind = match w {
                Warning::JkrOutsideValidity { .. } => "tabor",
                Warning::ImplausibleRadius { .. } => "radius",
                Warning::ImplausibleSpeed { .. } => "speed",
                Warning::ImplausibleMaterial { field, .. } => field,
            };
            (i, kind, w.to_string())
        })
        .collect()
}

/// Columns of f64 results, the `"method"` column (the code of the method that answered each
/// element) where `has_method`, and the warnings, as a dict of flat arrays (of floats and an
/// int method code for a `scalar` call: one element, every argument a float).
pub fn columns<'py>(
    py: Python<'py>,
    names: &[&str],
    columns: Columns,
    has_method: bool,
    scalar: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let dict = PyDict::new(py);
    let Columns {
        values,
        codes,
        warnings,
    } = columns;
    if scalar && codes.len() == 1 {
        // a call of floats: floats (and an int method code), no arrays
        for (name, v) in names.iter().zip(&values) {
            dict.set_item(*name, v[0])?;
        }
        if has_method {
            dict.set_item("method", codes[0])?;
        }
    } else {
        for (name, v) in names.iter().zip(values) {
            dict.set_item(*name, PyArray1::from_vec(py, v))?;
        }
        if has_method {
            dict.set_item("method", PyArray1::from_vec(py, codes))?;
        }
    }
    dict.set_item("warnings", warnings)?;
    Ok(dict)
}

pub fn or_nan(v: Option<f64>) -> f64 {
    v.unwrap_or(f64::NAN)
}

/// `method` by name: `"table"` or `"search"` (any case).
pub fn method(name: &str) -> PyResult<ThresholdMethod> {
    ThresholdMethod::from_name(name).ok_or_else(|| {
        PyValueError::new_err(format!("method = '{name}': must be 'table' or 'search'"))
    })
}

/// The code of a method in a `"method"` column (0: search, 1: table).
pub fn method_code(m: ThresholdMethod) -> u8 {
    match m {
        ThresholdMethod::Search => 0,
        ThresholdMethod::Table => 1,
    }
}

/// The search settings of a call, as the CLI's: only `rel_tol`, `v_max` and `method`
/// (`"table"` or `"search"`) differ from the defaults.
pub fn search_options(v_max: Option<f64>, rel_tol: f64, name: &str) -> PyResult<SearchOptions> {
    Ok(SearchOptions {
        rel_tol,
        v_max,
        method: method(name)?,
        ..SearchOptions::default()
    })
}

/// Defines a vectorised `#[pyfunction]` of bodies in contact, whose arguments are converted,
/// checked and broadcast here once:
///
/// ```text
/// elementwise! {
///     /// docs
///     fn name(py, e: Elements[a, b; k; gamma_sv], opt: Type, opt2: Type = "default") { body }
/// }
/// ```
///
/// is `pub fn name(material, radius, radius2, wall, a, b, k, opt, opt2="default",
/// gamma_sv=None)` in Python (`k` and `gamma_sv` only where named between the brackets): in
/// `body`, `a` and `b` are the contiguous `&[f64]` of the flat arrays `a` and `b`, and `e` the
/// [`Elements`] of the call (the common length of every array checked); `body` gives the dict
/// of columns. A threshold search names `opts: SearchOptions` as its only option: the arguments
/// `v_max, rel_tol, method`, the [`search_options`] of them in `body`.
macro_rules! elementwise {
    // a threshold search: `opts: SearchOptions` stands for the arguments `v_max, rel_tol, method`
    // and is their `SearchOptions` in the body
    (
        $(#[$attr:meta])*
        fn $name:ident($py:ident, $e:ident: Elements[$($arrays:tt)*], $o:ident: SearchOptions)
        $body:block
    ) => {
        $crate::args::elementwise! {
            $(#[$attr])*
            fn $name($py, $e: Elements[$($arrays)*], v_max: Option<f64>, rel_tol: f64, method: &str) {
                let $o = $crate::args::search_options(v_max, rel_tol, method)?;
                $body
            }
        }
    };
    (
        $(#[$attr:meta])*
        fn $name:ident(
            $py:ident,
            $e:ident: Elements[$($own:ident),*; $($k:ident)?; $($gamma:ident)?]
            $(, $opt:ident: $ty:ty $(= $default:tt)?)* $(,)?
        ) $body:block
    ) => {
        $(#[$attr])*
        #[pyfunction]
        #[pyo3(signature = (
            material, radius, radius2, wall, $($own,)* $($k,)? $($opt $(= $default)?,)*
            $($gamma = None)?
        ))]
        #[allow(clippy::too_many_arguments)]
        pub fn $name<'py>(
            $py: Python<'py>,
            material: $crate::material::Material,
            radius: $crate::args::Array<'py>,
            radius2: Option<$crate::args::Array<'py>>,
            wall: bool,
            $($own: $crate::args::Array<'py>,)*
            $($k: $crate::args::Array<'py>,)?
            $($opt: $ty,)*
            $($gamma: Option<$crate::args::Array<'py>>,)?
        ) -> PyResult<Bound<'py, pyo3::types::PyDict>> {
            let own_scalar = true $(&& $own.is_one())*;
            $(let $own = $crate::args::data(&$own, stringify!($own))?;)*
            let $e = $crate::args::Elements::new(
                &material,
                None $(.or($gamma.as_ref()))?,
                &radius,
                radius2.as_ref(),
                wall,
                None $(.or(Some(&$k)))?,
                &[$((stringify!($own), $own)),*],
                own_scalar,
            )?;
            $body
        }
    };
}
pub(crate) use elementwise;
