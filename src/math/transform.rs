//! Affine transformations with their inverse kept alongside.

use glam::{DAffine3, DMat3, DVec3};

/// An affine map and its inverse, so both directions cost one multiply.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transform {
    /// Maps points from the inner (object or pattern) space to the outer space.
    pub outer_from_inner: DAffine3,
    /// The inverse map, outer space to inner space.
    pub inner_from_outer: DAffine3,
}

impl Default for Transform {
    fn default() -> Self {
        Transform::IDENTITY
    }
}

impl Transform {
    /// The identity transformation.
    pub const IDENTITY: Transform = Transform {
        outer_from_inner: DAffine3::IDENTITY,
        inner_from_outer: DAffine3::IDENTITY,
    };

    /// A transformation from its forward map; `None` when the map is singular.
    pub fn from_affine(outer_from_inner: DAffine3) -> Option<Transform> {
        let det = outer_from_inner.matrix3.determinant();
        if !det.is_finite() || det.abs() < 1e-300 {
            return None;
        }
        Some(Transform {
            outer_from_inner,
            inner_from_outer: outer_from_inner.inverse(),
        })
    }

    /// A translation by `offset`.
    pub fn translation(offset: DVec3) -> Transform {
        Transform {
            outer_from_inner: DAffine3::from_translation(offset),
            inner_from_outer: DAffine3::from_translation(-offset),
        }
    }

    /// A scaling; `None` when a factor is zero.
    pub fn scaling(factors: DVec3) -> Option<Transform> {
        Transform::from_affine(DAffine3::from_scale(factors))
    }

    /// POV-Ray's `rotate <x, y, z>`: degrees about x, then y, then z (left-handed, as POV-Ray).
    ///
    /// ```
    /// use durer::math::Transform;
    /// use glam::DVec3;
    /// // POV-Ray turns +x into -z when rotating 90 degrees about y.
    /// let turned = Transform::rotation_degrees(DVec3::new(0.0, 90.0, 0.0)).point_to_outer(DVec3::X);
    /// assert!((turned - DVec3::new(0.0, 0.0, -1.0)).length() < 1e-12);
    /// ```
    pub fn rotation_degrees(angles: DVec3) -> Transform {
        let r = angles * (std::f64::consts::PI / 180.0);
        // POV-Ray rotates about X, then Y, then Z; its left-handed system matches glam's
        // right-handed rotation matrices applied to the same coordinates.
        let m =
            DMat3::from_rotation_z(r.z) * DMat3::from_rotation_y(r.y) * DMat3::from_rotation_x(r.x);
        Transform {
            outer_from_inner: DAffine3::from_mat3(m),
            inner_from_outer: DAffine3::from_mat3(m.transpose()),
        }
    }

    /// `then` applied after `self`: the result maps inner space of `self` to outer space of `then`.
    pub fn then(&self, then: &Transform) -> Transform {
        Transform {
            outer_from_inner: then.outer_from_inner * self.outer_from_inner,
            inner_from_outer: self.inner_from_outer * then.inner_from_outer,
        }
    }

    /// The inverse transformation.
    pub fn inverse(&self) -> Transform {
        Transform {
            outer_from_inner: self.inner_from_outer,
            inner_from_outer: self.outer_from_inner,
        }
    }

    /// Maps a point from inner to outer space.
    pub fn point_to_outer(&self, p: DVec3) -> DVec3 {
        self.outer_from_inner.transform_point3(p)
    }

    /// Maps a point from outer to inner space.
    pub fn point_to_inner(&self, p: DVec3) -> DVec3 {
        self.inner_from_outer.transform_point3(p)
    }

    /// Maps a direction from inner to outer space.
    pub fn vector_to_outer(&self, v: DVec3) -> DVec3 {
        self.outer_from_inner.transform_vector3(v)
    }

    /// Maps a direction from outer to inner space.
    pub fn vector_to_inner(&self, v: DVec3) -> DVec3 {
        self.inner_from_outer.transform_vector3(v)
    }

    /// Maps a surface normal from inner to outer space (inverse transpose), not normalised.
    pub fn normal_to_outer(&self, n: DVec3) -> DVec3 {
        self.inner_from_outer.matrix3.transpose() * n
    }
}
