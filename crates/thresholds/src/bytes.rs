//! The binary form of the embedded tables, written once for the master tables
//! ([`crate::master::binary`]) and the restitution tables ([`crate::restitution::format`]):
//! little-endian `f64` numbers (counts and flags as whole numbers), first a magic of 8 bytes, the
//! number of tables and each one's k, byte offset and length, then what the tables share (the
//! master tables' end curves), then the tables. Every value is one `f64`, so every array lies
//! on a multiple of 8 bytes: the library embeds the form aligned for `f64`
//! ([`crate::master`]) and borrows its arrays in place ([`Reader::fs_borrowed`]), so a
//! process's first answer reads only the pages it touches. `std` and `bytemuck` only: the build
//! script includes this file, as it includes its two users.

use std::borrow::Cow;

/// Appends numbers to a binary form.
#[derive(Default)]
pub struct Writer(pub Vec<u8>);

impl Writer {
    /// One number.
    pub fn f(&mut self, v: f64) {
        self.0.extend_from_slice(&v.to_le_bytes());
    }

    /// A count or an offset.
    pub fn n(&mut self, v: usize) {
        self.f(v as f64);
    }

    /// A flag: 1 or 0.
    pub fn flag(&mut self, v: bool) {
        self.f(f64::from(u8::from(v)));
    }

    /// The length of `v`, then its numbers.
    pub fn fs(&mut self, v: &[f64]) {
        self.n(v.len());
        for &x in v {
            self.f(x);
        }
    }

    /// The length of `v`, then its flags.
    pub fn flags(&mut self, v: &[bool]) {
        self.n(v.len());
        for &x in v {
            self.flag(x);
        }
    }

    /// The length of `items`, then each written by `item`.
    pub fn list<T>(&mut self, items: &[T], mut item: impl FnMut(&mut Self, &T)) {
        self.n(items.len());
        for x in items {
            item(self, x);
        }
    }
}

/// Reads numbers from a binary form; `None` past its end or at a number that is not what it
/// should be.
pub struct Reader<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl<'a> Reader<'a> {
    /// A reader of `bytes` from byte `at`.
    pub fn new(bytes: &'a [u8], at: usize) -> Self {
        Reader { bytes, at }
    }

    /// One number.
    pub fn f(&mut self) -> Option<f64> {
        let b = self.bytes.get(self.at..self.at + 8)?;
        self.at += 8;
        Some(f64::from_le_bytes(b.try_into().ok()?))
    }

    /// A count or an offset.
    pub fn n(&mut self) -> Option<usize> {
        let v = self.f()?;
        (v >= 0.0 && v.fract() == 0.0 && v < 1e9).then_some(v as usize)
    }

    /// A flag ([`Writer::flag`]).
    pub fn flag(&mut self) -> Option<bool> {
        Some(self.f()? == 1.0)
    }

    /// Numbers after their length ([`Writer::fs`]).
    pub fn fs(&mut self) -> Option<Vec<f64>> {
        self.fs_borrowed().map(Cow::into_owned)
    }

    /// Numbers after their length ([`Writer::fs`]), borrowed from the binary form where it lies
    /// aligned for `f64` on a little-endian machine (the embedded tables), else copied.
    pub fn fs_borrowed(&mut self) -> Option<Cow<'a, [f64]>> {
        let n = self.n()?;
        let bytes = self.bytes.get(self.at..self.at + 8 * n)?;
        self.at += 8 * n;
        if cfg!(target_endian = "little") {
            if let Ok(v) = bytemuck::try_cast_slice::<u8, f64>(bytes) {
                return Some(Cow::Borrowed(v));
            }
        }
        Some(Cow::Owned(
            bytes
                .chunks_exact(8)
                .map(|b| <[u8; 8]>::try_from(b).map_or(f64::NAN, f64::from_le_bytes))
                .collect(),
        ))
    }

    /// Flags after their length ([`Writer::flags`]).
    pub fn flags(&mut self) -> Option<Vec<bool>> {
        Some(self.fs()?.into_iter().map(|v| v == 1.0).collect())
    }

    /// Items after their count, each read by `item` ([`Writer::list`]).
    pub fn list<T>(&mut self, mut item: impl FnMut(&mut Self) -> Option<T>) -> Option<Vec<T>> {
        let n = self.n()?;
        let mut items = Vec::with_capacity(n);
        for _ in 0..n {
            items.push(item(self)?);
        }
        Some(items)
    }
}

/// The binary form of `tables` (each one's k and bytes) after `magic`, with `shared` between
/// the index and the tables.
pub fn to_bytes(magic: &[u8; 8], shared: &[u8], tables: &[(f64, Vec<u8>)]) -> Vec<u8> {
    let mut w = Writer::default();
    w.0.extend_from_slice(magic);
    w.n(tables.len());
    let mut offset = shared_at(tables.len()) + shared.len();
    for (k, b) in tables {
        w.f(*k);
        w.n(offset);
        w.n(b.len());
        offset += b.len();
    }
    w.0.extend_from_slice(shared);
    for (_, b) in tables {
        w.0.extend_from_slice(b);
    }
    w.0
}

/// Where what the tables share starts: after the magic, the count and the index of `n` tables.
fn shared_at(n: usize) -> usize {
    8 + 8 + 24 * n
}

/// `(k, offset, length)` of each table of a binary form that starts with `magic`.
pub fn index(bytes: &[u8], magic: &[u8; 8]) -> Option<Vec<(f64, usize, usize)>> {
    if bytes.get(..8)? != magic {
        return None;
    }
    let mut r = Reader::new(bytes, 8);
    let n = r.n()?;
    (0..n).map(|_| Some((r.f()?, r.n()?, r.n()?))).collect()
}

/// A reader of what the tables share.
pub fn shared<'a>(bytes: &'a [u8], magic: &[u8; 8]) -> Option<Reader<'a>> {
    let n = index(bytes, magic)?.len();
    Some(Reader::new(bytes, shared_at(n)))
}

/// A reader of table `i`.
pub fn table<'a>(bytes: &'a [u8], magic: &[u8; 8], i: usize) -> Option<Reader<'a>> {
    let (_, offset, len) = *index(bytes, magic)?.get(i)?;
    Some(Reader::new(bytes.get(offset..offset + len)?, 0))
}
