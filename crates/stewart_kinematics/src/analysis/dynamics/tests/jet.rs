//! Second-order automatic differentiation: a value with its first and second derivatives
//! along one parameter, carried exactly (to rounding) through arithmetic and the
//! functions the platform's positions are made of.

use std::ops::{Add, Div, Mul, Neg, Sub};

/// `f(s)` at a point with `f'` and `f''`.
#[derive(Clone, Copy, Debug)]
pub struct Jet {
    pub v: f64,
    pub d1: f64,
    pub d2: f64,
}

impl Jet {
    /// A constant.
    pub fn c(v: f64) -> Self {
        Self {
            v,
            d1: 0.0,
            d2: 0.0,
        }
    }

    /// A value with its first and second derivatives.
    pub fn new(v: f64, d1: f64, d2: f64) -> Self {
        Self { v, d1, d2 }
    }

    /// `f(self)` given `f`, `f'` and `f''` at the value (the chain rule to second order).
    fn chain(self, f: f64, df: f64, ddf: f64) -> Self {
        Self {
            v: f,
            d1: df * self.d1,
            d2: ddf * self.d1 * self.d1 + df * self.d2,
        }
    }

    pub fn sin(self) -> Self {
        let (s, c) = self.v.sin_cos();
        self.chain(s, c, -s)
    }

    pub fn cos(self) -> Self {
        let (s, c) = self.v.sin_cos();
        self.chain(c, -s, -c)
    }

    pub fn sqrt(self) -> Self {
        let r = self.v.sqrt();
        self.chain(r, 0.5 / r, -0.25 / (r * self.v))
    }

    pub fn asin(self) -> Self {
        let q = 1.0 - self.v * self.v;
        self.chain(self.v.asin(), 1.0 / q.sqrt(), self.v / (q * q.sqrt()))
    }

    /// `atan2(self, x)`.
    pub fn atan2(self, x: Jet) -> Self {
        let y = self;
        let d = x.v * x.v + y.v * y.v;
        let n = x.v * y.d1 - y.v * x.d1;
        let dn = x.v * y.d2 - y.v * x.d2;
        let dd = 2.0 * (x.v * x.d1 + y.v * y.d1);
        Self {
            v: y.v.atan2(x.v),
            d1: n / d,
            d2: (dn * d - n * dd) / (d * d),
        }
    }
}

impl Add for Jet {
    type Output = Jet;
    fn add(self, o: Jet) -> Jet {
        Jet::new(self.v + o.v, self.d1 + o.d1, self.d2 + o.d2)
    }
}

impl Sub for Jet {
    type Output = Jet;
    fn sub(self, o: Jet) -> Jet {
        Jet::new(self.v - o.v, self.d1 - o.d1, self.d2 - o.d2)
    }
}

impl Neg for Jet {
    type Output = Jet;
    fn neg(self) -> Jet {
        Jet::new(-self.v, -self.d1, -self.d2)
    }
}

impl Mul for Jet {
    type Output = Jet;
    fn mul(self, o: Jet) -> Jet {
        Jet::new(
            self.v * o.v,
            self.d1 * o.v + self.v * o.d1,
            self.d2 * o.v + 2.0 * self.d1 * o.d1 + self.v * o.d2,
        )
    }
}

impl Mul<f64> for Jet {
    type Output = Jet;
    fn mul(self, k: f64) -> Jet {
        Jet::new(self.v * k, self.d1 * k, self.d2 * k)
    }
}

impl Div for Jet {
    type Output = Jet;
    fn div(self, o: Jet) -> Jet {
        let v = self.v / o.v;
        let d1 = (self.d1 - v * o.d1) / o.v;
        let d2 = (self.d2 - 2.0 * d1 * o.d1 - v * o.d2) / o.v;
        Jet::new(v, d1, d2)
    }
}

/// A 3-vector of jets.
pub type V3 = [Jet; 3];

pub fn v3(x: [f64; 3]) -> V3 {
    x.map(Jet::c)
}

pub fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

pub fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

pub fn scale(a: V3, k: Jet) -> V3 {
    [a[0] * k, a[1] * k, a[2] * k]
}

pub fn dot(a: V3, b: V3) -> Jet {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub fn norm(a: V3) -> Jet {
    dot(a, a).sqrt()
}

/// A 3×3 matrix of jets, rows first.
pub type M3 = [[Jet; 3]; 3];

pub fn mat_vec(m: &M3, x: V3) -> V3 {
    [dot(m[0], x), dot(m[1], x), dot(m[2], x)]
}

pub fn mat_mul(a: &M3, b: &M3) -> M3 {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j])
    })
}

#[test]
fn jets_differentiate_a_composite_function_exactly() {
    // f(s) = atan2(sin s, 2 + cos s) · sqrt(1 + s²) / (1 + asin(s/3)), against central
    // differences of f and f' at s = 0.4 (h = 1e-4: error well under 1e-7).
    let f = |s: Jet| {
        let a = s.sin().atan2(Jet::c(2.0) + s.cos());
        let b = (Jet::c(1.0) + s * s).sqrt();
        a * b / (Jet::c(1.0) + (s * (1.0 / 3.0)).asin())
    };
    let at = |s: f64| f(Jet::new(s, 1.0, 0.0));
    let (s, h) = (0.4, 1e-4);
    let j = at(s);
    let d1 = (at(s + h).v - at(s - h).v) / (2.0 * h);
    let d2 = (at(s + h).d1 - at(s - h).d1) / (2.0 * h);
    assert!((j.d1 - d1).abs() < 1e-7, "{} vs {d1}", j.d1);
    assert!((j.d2 - d2).abs() < 1e-7, "{} vs {d2}", j.d2);
}
