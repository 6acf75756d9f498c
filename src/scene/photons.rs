//! Photon mapping settings: the `photons { .. }` blocks of `global_settings`, objects and
//! light sources.
//!
//! In: values parsed by `eval::photons`. Out: [`PhotonSettings`], [`ObjectPhotons`] and
//! [`LightPhotons`], read by `geometry` (material flags) and `render::photons`. Holds: the
//! defaults are POV-Ray 3.7's as it renders them (lights shoot reflected and refracted
//! photons unless told otherwise, although the manual's table says off).

/// How many photons are shot: by spacing or by a total count.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PhotonDensity {
    /// `spacing S`: the average distance between photons arriving at a target.
    Spacing(f64),
    /// `count N`: about this many photons in all.
    Count(u32),
}

/// The global `photons { }` block (POV-Ray 3.7 defaults).
#[derive(Clone, Debug, PartialEq)]
pub struct PhotonSettings {
    /// `spacing` or `count`.
    pub density: PhotonDensity,
    /// Fewest photons a gather should use (`gather MIN, MAX`, default 20).
    pub gather_min: u32,
    /// Most photons a gather uses (default 100).
    pub gather_max: u32,
    /// `media MAX_STEPS, FACTOR`: media photons are deposited in scattering media, at
    /// most `MAX_STEPS` per stretch of a photon's path (0: none).
    pub media_steps: u32,
    /// `media` second value: media photons lie `FACTOR` times the spacing apart along a
    /// photon's path (default 1).
    pub media_factor: f64,
    /// Jitter of shooting directions, as a fraction of the angular spacing (default 0.4).
    pub jitter: f64,
    /// Bounces of a photon (`max_trace_level`; the scene's when `None`).
    pub max_trace_level: Option<u32>,
    /// Photons weaker than this are dropped (`adc_bailout`; the scene's when `None`).
    pub adc_bailout: Option<f64>,
    /// `autostop F`: a fraction of the target's cone after which a ring of photons that
    /// all miss ends the shooting at that target (default 0: after the first hit).
    pub autostop: f64,
    /// `expand_thresholds INCREASE, MIN` (defaults 0.2 and 40).
    pub expand_increase: f64,
    /// See [`PhotonSettings::expand_increase`].
    pub expand_min: u32,
    /// `radius` gather radius for surface photons (0: estimated).
    pub radius: f64,
    /// `radius` second value: multiplies the gather radius (default 1).
    pub radius_multiplier: f64,
    /// `radius` third value: gather radius for media photons (0: estimated).
    pub media_radius: f64,
    /// `radius` fourth value: multiplies the media photons' gather radius (default 1).
    pub media_radius_multiplier: f64,
}

impl Default for PhotonSettings {
    fn default() -> Self {
        PhotonSettings {
            density: PhotonDensity::Count(20_000),
            gather_min: 20,
            gather_max: 100,
            media_steps: 0,
            media_factor: 1.0,
            jitter: 0.4,
            max_trace_level: None,
            adc_bailout: None,
            autostop: 0.0,
            expand_increase: 0.2,
            expand_min: 40,
            radius: 0.0,
            radius_multiplier: 1.0,
            media_radius: 0.0,
            media_radius_multiplier: 1.0,
        }
    }
}

/// The items of an object's `photons { }` block that were written (see
/// [`ObjectPhotons::given`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PhotonItemsGiven {
    pub target: bool,
    pub refraction: bool,
    pub reflection: bool,
    pub collect: bool,
    pub pass_through: bool,
}

impl PhotonItemsGiven {
    /// True when the block said anything.
    pub fn any(&self) -> bool {
        self.target || self.refraction || self.reflection || self.collect || self.pass_through
    }
}

/// An object's `photons { }` block, packed into eight bytes (scenes hold many objects).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ObjectPhotons {
    /// `target [MULTIPLIER]`: the multiplier's bits (photons are shot at the object, spaced
    /// by the global spacing times it); 0 when the object is no target.
    target_bits: u32,
    /// The on/off items, one bit each (see the `*_BIT` constants).
    flags: u8,
    /// Which items the scene set explicitly (the same bits, plus [`Self::TARGET_BIT`]),
    /// so a CSG's block can be merged into its children's item by item.
    explicit: u8,
}

impl ObjectPhotons {
    const REFRACTION_BIT: u8 = 1;
    const REFLECTION_BIT: u8 = 2;
    const COLLECT_BIT: u8 = 4;
    const PASS_THROUGH_BIT: u8 = 8;
    /// In `explicit` only: `target` was given.
    const TARGET_BIT: u8 = 16;

    /// The spacing multiplier when photons are shot at the object.
    pub fn target(&self) -> Option<f64> {
        (self.target_bits != 0).then(|| f64::from(f32::from_bits(self.target_bits)))
    }

    /// Makes the object a target with this spacing multiplier (`None`: no target).
    /// Multipliers that are not positive and finite count as 1.
    pub fn set_target(&mut self, multiplier: Option<f64>) {
        self.explicit |= Self::TARGET_BIT;
        self.target_bits = match multiplier {
            None => 0,
            Some(m) if m > 0.0 && m.is_finite() => (m as f32).max(f32::MIN_POSITIVE).to_bits(),
            Some(_) => 1f32.to_bits(),
        };
    }

    /// `refraction on`: photons pass into the object, bent.
    pub fn refraction(&self) -> bool {
        self.flags & Self::REFRACTION_BIT != 0
    }

    /// `reflection on`: photons bounce off the object.
    pub fn reflection(&self) -> bool {
        self.flags & Self::REFLECTION_BIT != 0
    }

    /// `collect` (default on): photons landing on the object are stored and shown.
    pub fn collect(&self) -> bool {
        self.flags & Self::COLLECT_BIT != 0
    }

    /// `pass_through`: photons on their way from the light cross the object unchanged,
    /// even when it is a target (such a target casts an ordinary filtered shadow);
    /// `no_shadow`, kept on the material, lets photons cross at any bounce.
    pub fn pass_through(&self) -> bool {
        self.flags & Self::PASS_THROUGH_BIT != 0
    }

    /// Whether photons of a light with `light`'s block refract at the object: the light
    /// shoots refracted photons and the object says `refraction on`, or says nothing of
    /// refraction while the light says `refraction on` itself (measured in POV-Ray 3.7:
    /// then every object without its own `refraction` item refracts its photons).
    pub fn refracts_for(&self, light: &LightPhotons) -> bool {
        light.refraction
            && (self.refraction()
                || (light.refraction_given && self.explicit & Self::REFRACTION_BIT == 0))
    }

    /// Whether photons of a light with `light`'s block reflect off the object: as
    /// [`Self::refracts_for`], for reflection.
    pub fn reflects_for(&self, light: &LightPhotons) -> bool {
        light.reflection
            && (self.reflection()
                || (light.reflection_given && self.explicit & Self::REFLECTION_BIT == 0))
    }

    /// Sets `refraction`.
    pub fn set_refraction(&mut self, on: bool) {
        self.set(Self::REFRACTION_BIT, on);
    }

    /// Sets `reflection`.
    pub fn set_reflection(&mut self, on: bool) {
        self.set(Self::REFLECTION_BIT, on);
    }

    /// Sets `collect`.
    pub fn set_collect(&mut self, on: bool) {
        self.set(Self::COLLECT_BIT, on);
    }

    /// Sets `pass_through`.
    pub fn set_pass_through(&mut self, on: bool) {
        self.set(Self::PASS_THROUGH_BIT, on);
    }

    /// Applies a CSG's block to one of its children's (measured in POV-Ray 3.7): every
    /// item the CSG set explicitly replaces the child's, even one the child set itself
    /// (a union's `refraction on` beats a child's `refraction off` and the reverse); the
    /// child keeps its own items where the CSG set nothing.
    pub fn inherit(&mut self, parent: &ObjectPhotons) {
        if parent.explicit & Self::TARGET_BIT != 0 {
            self.target_bits = parent.target_bits;
            // A CSG target is shot at whole: a part's own `pass_through` does not let its
            // photons pass (measured: POV-Ray refracts them there), unless the CSG sets it.
            if parent.target_bits != 0 && parent.explicit & Self::PASS_THROUGH_BIT == 0 {
                self.flags &= !Self::PASS_THROUGH_BIT;
            }
        }
        let from_parent = parent.explicit & !Self::TARGET_BIT;
        self.flags = (self.flags & !from_parent) | (parent.flags & from_parent);
        self.explicit |= parent.explicit;
    }

    /// Which items the scene's blocks gave explicitly (what a writer must say again).
    pub fn given(&self) -> PhotonItemsGiven {
        let bit = |b: u8| self.explicit & b != 0;
        PhotonItemsGiven {
            target: bit(Self::TARGET_BIT),
            refraction: bit(Self::REFRACTION_BIT),
            reflection: bit(Self::REFLECTION_BIT),
            collect: bit(Self::COLLECT_BIT),
            pass_through: bit(Self::PASS_THROUGH_BIT),
        }
    }

    fn set(&mut self, bit: u8, on: bool) {
        self.explicit |= bit;
        if on {
            self.flags |= bit;
        } else {
            self.flags &= !bit;
        }
    }
}

impl Default for ObjectPhotons {
    fn default() -> Self {
        ObjectPhotons {
            target_bits: 0,
            flags: Self::COLLECT_BIT,
            explicit: 0,
        }
    }
}

/// A light source's `photons { }` block.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LightPhotons {
    /// The light's photons refract (default on).
    pub refraction: bool,
    /// The light's photons reflect (default on).
    pub reflection: bool,
    /// The block says `refraction` itself (then objects without their own `refraction`
    /// item refract the light's photons).
    pub refraction_given: bool,
    /// The block says `reflection` itself (as `refraction_given`).
    pub reflection_given: bool,
}

impl Default for LightPhotons {
    fn default() -> Self {
        LightPhotons {
            refraction: true,
            reflection: true,
            refraction_given: false,
            reflection_given: false,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn block(items: impl FnOnce(&mut ObjectPhotons)) -> ObjectPhotons {
        let mut photons = ObjectPhotons::default();
        items(&mut photons);
        photons
    }

    #[test]
    fn a_child_keeps_its_own_items_where_the_csg_set_none() {
        let parent = block(|p| {
            p.set_target(Some(2.0));
            p.set_refraction(true);
        });
        let mut child = block(|c| c.set_collect(false));
        child.inherit(&parent);
        assert_eq!(child.target(), Some(2.0));
        assert!(child.refraction());
        assert!(!child.collect());
        assert!(!child.reflection());
    }

    #[test]
    fn the_csg_items_beat_the_child_items() {
        let parent = block(|p| p.set_refraction(false));
        let mut child = block(|c| {
            c.set_refraction(true);
            c.set_target(Some(1.0));
        });
        child.inherit(&parent);
        assert!(!child.refraction());
        assert_eq!(child.target(), Some(1.0));
        let mut grandchild = ObjectPhotons::default();
        grandchild.inherit(&child);
        assert!(!grandchild.refraction());
        assert_eq!(grandchild.target(), Some(1.0));
    }

    #[test]
    fn a_csg_target_drops_a_part_s_own_pass_through() {
        let mut child = block(|c| c.set_pass_through(true));
        child.inherit(&block(|p| p.set_target(Some(1.0))));
        assert!(!child.pass_through());
        let mut child = block(|c| c.set_pass_through(true));
        child.inherit(&block(|p| {
            p.set_target(Some(1.0));
            p.set_pass_through(true);
        }));
        assert!(child.pass_through());
        let mut child = block(|c| c.set_pass_through(true));
        child.inherit(&block(|p| p.set_collect(false)));
        assert!(child.pass_through());
    }

    #[test]
    fn a_light_s_own_items_apply_to_objects_without_theirs() {
        let light = LightPhotons {
            refraction_given: true,
            reflection_given: true,
            ..LightPhotons::default()
        };
        let silent = block(|p| p.set_target(Some(1.0)));
        assert!(silent.refracts_for(&light) && silent.reflects_for(&light));
        assert!(!silent.refracts_for(&LightPhotons::default()));
        let refusing = block(|p| {
            p.set_refraction(false);
            p.set_reflection(false);
        });
        assert!(!refusing.refracts_for(&light) && !refusing.reflects_for(&light));
        let off = LightPhotons {
            refraction: false,
            ..light
        };
        assert!(!block(|p| p.set_refraction(true)).refracts_for(&off));
    }

    #[test]
    fn an_empty_block_changes_nothing() {
        let mut child = block(|c| c.set_pass_through(true));
        child.inherit(&ObjectPhotons::default());
        assert!(child.pass_through());
        assert!(child.collect());
    }
}
