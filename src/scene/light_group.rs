//! Light groups: `light_group { OBJECTS.. LIGHTS.. [global_lights on|off] }`.
//!
//! In: nothing (data definition). Out: [`LightGroup`], the group a surface belongs to, and
//! the rule saying which lights light which surfaces. Holds: group ids are unique within
//! one scene; a light's group is `None` for the scene's ordinary (global) lights.

/// The light group an object's surfaces belong to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct LightGroup {
    /// The group's id, shared with the lights written inside it.
    pub id: u32,
    /// `global_lights on`: the scene's own lights light the group's objects too.
    pub global_lights: bool,
}

impl LightGroup {
    /// Whether a light of group `light` (`None`: a scene light) lights a surface of group
    /// `surface` (`None`: an object outside every group). Group lights light only their
    /// group; scene lights light every surface outside groups and the surfaces of groups
    /// with `global_lights on`.
    pub fn lights(light: Option<u32>, surface: Option<LightGroup>) -> bool {
        match (light, surface) {
            (None, None) => true,
            (None, Some(group)) => group.global_lights,
            (Some(_), None) => false,
            (Some(id), Some(group)) => id == group.id,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lights_stay_in_their_group() {
        let closed = LightGroup {
            id: 1,
            global_lights: false,
        };
        let open = LightGroup {
            id: 2,
            global_lights: true,
        };
        assert!(LightGroup::lights(None, None));
        assert!(!LightGroup::lights(None, Some(closed)));
        assert!(LightGroup::lights(None, Some(open)));
        assert!(!LightGroup::lights(Some(1), None));
        assert!(LightGroup::lights(Some(1), Some(closed)));
        assert!(!LightGroup::lights(Some(1), Some(open)));
    }
}
