//! Turns fuzzer bytes into argument values. Every draw consumes a few bytes; once the input is
//! used up every draw returns zero bits, so any byte string decodes to some call.
//!
//! Also the small decoding helpers every case shares: [`len`] (a Fortran count as a length),
//! [`bits`] (bit patterns, to compare arrays NaN-exactly), [`Bytes::reals`] and [`Bytes::name`].
//!
//! Reals are drawn by class (one selector byte) so the fuzzer reaches the values that break
//! floating-point code — NaN, ±Inf, ±0, subnormals, f64::MAX, magnitudes near the overflow and
//! underflow thresholds, raw bit patterns — as easily as ordinary ones.

/// A cursor over the fuzzer's bytes.
pub struct Bytes<'a> {
    data: &'a [u8],
}

impl<'a> Bytes<'a> {
    /// Reads from the start of `data`.
    pub fn new(data: &'a [u8]) -> Self {
        Bytes { data }
    }

    /// The next byte, 0 when the input is used up.
    pub fn u8(&mut self) -> u8 {
        match self.data.split_first() {
            Some((b, rest)) => {
                self.data = rest;
                *b
            }
            None => 0,
        }
    }

    /// The next two bytes, little-endian.
    pub fn u16(&mut self) -> u16 {
        u16::from_le_bytes([self.u8(), self.u8()])
    }

    /// The next eight bytes, little-endian.
    pub fn u64(&mut self) -> u64 {
        let mut b = [0u8; 8];
        for x in &mut b {
            *x = self.u8();
        }
        u64::from_le_bytes(b)
    }

    /// One of `choices`, by the next byte.
    pub fn pick<T: Copy>(&mut self, choices: &[T]) -> T {
        choices[usize::from(self.u8()) % choices.len()]
    }

    /// `choices[k]` for the next byte k; past their end, `otherwise(k)` (the decoders' choice of
    /// the argument passed as NULL, where most bytes choose none).
    pub fn choose<T: Copy>(&mut self, choices: &[T], otherwise: impl Fn(u8) -> T) -> T {
        let k = self.u8();
        choices
            .get(usize::from(k))
            .copied()
            .unwrap_or_else(|| otherwise(k))
    }

    /// `len` raw bytes (fewer, padded with zeros, when the input runs out).
    pub fn bytes(&mut self, len: usize) -> Vec<u8> {
        (0..len).map(|_| self.u8()).collect()
    }

    /// A real of any class: ordinary magnitudes most of the time, and every special value.
    pub fn real(&mut self) -> f64 {
        let class = self.u8();
        let sign = if class & 0x80 != 0 { -1.0 } else { 1.0 };
        match class & 0x7f {
            0 => 0.0 * sign,
            1 => f64::NAN,
            2 => f64::INFINITY * sign,
            // Subnormal: a random mantissa with a zero exponent (never zero by itself).
            3 => sign * f64::from_bits((self.u64() & 0x000f_ffff_ffff_ffff).max(1)),
            4 => sign * f64::MIN_POSITIVE,
            5 => sign * f64::MAX,
            // Huge: 1.x · 10^(150..=308), where squares and products overflow.
            6 => sign * self.mantissa() * 10f64.powi(150 + i32::from(self.u8()) % 159),
            // Tiny: 1.x · 10^(-323..=-150), where squares and products underflow.
            7 => sign * self.mantissa() * 10f64.powi(-150 - i32::from(self.u8()) % 174),
            // Any bit pattern (NaN payloads included).
            8 => f64::from_bits(self.u64()),
            // Small integers, exact: law codes, stick modes, 0/1/2 flags.
            9..=15 => sign * f64::from(self.u8() % 8),
            // Ordinary: 1.x · 10^(-12..=12).
            _ => sign * self.mantissa() * 10f64.powi(i32::from(self.u8() % 25) - 12),
        }
    }

    /// A real ≥ 1 (mostly ordinary), for `PNEWDT` on entry: hosts pass a large value.
    pub fn large(&mut self) -> f64 {
        match self.u8() % 8 {
            0 => 1.0,
            1 => f64::MAX,
            2 => f64::INFINITY,
            3 => f64::NAN,
            _ => 1e36,
        }
    }

    /// 1.0 ≤ m < 10.
    fn mantissa(&mut self) -> f64 {
        1.0 + 9.0 * f64::from(self.u16()) / 65536.0
    }
}

impl Bytes<'_> {
    /// `n` reals of any class.
    pub fn reals(&mut self, n: usize) -> Vec<f64> {
        (0..n).map(|_| self.real()).collect()
    }

    /// A `CHARACTER` argument: 80 bytes mostly (else 0..=127), up to 12 capital letters then
    /// blanks.
    pub fn name(&mut self) -> Vec<u8> {
        self.name_padded(true, b' ')
    }

    /// A `CHARACTER` argument as [`Bytes::name`] draws it, its up to 12 leading bytes mapped to
    /// capital letters or left raw (`letters`), padded with `pad` to the hidden length.
    pub fn name_padded(&mut self, letters: bool, pad: u8) -> Vec<u8> {
        let l = usize::from(self.u8());
        let l = if l < 128 { 80 } else { l - 128 };
        let printed = usize::from(self.u8() % 13);
        let mut v = self.bytes(l.min(printed));
        if letters {
            for x in &mut v {
                *x = b'A' + *x % 26;
            }
        }
        v.resize(l, pad);
        v
    }

    /// An ordinary positive real, 1.x · 10^(-6..=6): material parameters that are valid.
    pub fn positive(&mut self) -> f64 {
        self.mantissa() * 10f64.powi(i32::from(self.u8() % 13) - 6)
    }

    /// A real in [0, 1], in steps of 1/255.
    pub fn unit(&mut self) -> f64 {
        f64::from(self.u8()) / 255.0
    }
}

/// A Fortran count as a length: a negative one is 0.
pub fn len(n: i32) -> usize {
    usize::try_from(n).unwrap_or(0)
}

/// The bit patterns of `v`, so that two arrays compare equal only when every entry (NaN
/// payloads and signed zeros included) is the same.
pub fn bits(v: &[f64]) -> Vec<u64> {
    v.iter().map(|x| x.to_bits()).collect()
}
