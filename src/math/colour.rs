//! Colours as POV-Ray models them: red, green, blue plus filter and transmit.

use std::ops::{Add, Mul, Sub};

/// A POV-Ray colour: linear red, green, blue, then filter and transmit (both 0 = opaque).
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Colour {
    /// Red channel.
    pub red: f64,
    /// Green channel.
    pub green: f64,
    /// Blue channel.
    pub blue: f64,
    /// Filtered transparency: light passes tinted by the colour.
    pub filter: f64,
    /// Transmitted transparency: light passes untinted.
    pub transmit: f64,
}

impl Colour {
    /// Opaque black.
    pub const BLACK: Colour = Colour::rgb(0.0, 0.0, 0.0);
    /// Opaque white.
    pub const WHITE: Colour = Colour::rgb(1.0, 1.0, 1.0);

    /// An opaque colour from its three channels.
    pub const fn rgb(red: f64, green: f64, blue: f64) -> Colour {
        Colour {
            red,
            green,
            blue,
            filter: 0.0,
            transmit: 0.0,
        }
    }

    /// A colour from all five components.
    pub const fn rgbft(red: f64, green: f64, blue: f64, filter: f64, transmit: f64) -> Colour {
        Colour {
            red,
            green,
            blue,
            filter,
            transmit,
        }
    }

    /// A grey with the same value in all three channels.
    pub const fn grey(value: f64) -> Colour {
        Colour::rgb(value, value, value)
    }

    /// The five components in order r, g, b, filter, transmit.
    pub fn to_array(self) -> [f64; 5] {
        [self.red, self.green, self.blue, self.filter, self.transmit]
    }

    /// A colour from five components in order r, g, b, filter, transmit.
    pub fn from_array(c: [f64; 5]) -> Colour {
        Colour::rgbft(c[0], c[1], c[2], c[3], c[4])
    }

    /// The colour channels as a vector, dropping filter and transmit.
    pub fn rgb_vec(self) -> glam::DVec3 {
        glam::DVec3::new(self.red, self.green, self.blue)
    }

    /// Linear interpolation of all five components: `self` at 0, `other` at 1.
    pub fn lerp(self, other: Colour, fraction: f64) -> Colour {
        self + (other - self) * fraction
    }
}

impl Add for Colour {
    type Output = Colour;
    fn add(self, o: Colour) -> Colour {
        Colour::rgbft(
            self.red + o.red,
            self.green + o.green,
            self.blue + o.blue,
            self.filter + o.filter,
            self.transmit + o.transmit,
        )
    }
}

impl Sub for Colour {
    type Output = Colour;
    fn sub(self, o: Colour) -> Colour {
        Colour::rgbft(
            self.red - o.red,
            self.green - o.green,
            self.blue - o.blue,
            self.filter - o.filter,
            self.transmit - o.transmit,
        )
    }
}

impl Mul<f64> for Colour {
    type Output = Colour;
    fn mul(self, k: f64) -> Colour {
        Colour::rgbft(
            self.red * k,
            self.green * k,
            self.blue * k,
            self.filter * k,
            self.transmit * k,
        )
    }
}
