//! Radiosity settings: the `radiosity { .. }` block of `global_settings`.
//!
//! In: values parsed by `eval::radiosity`. Out: [`RadiositySettings`], read by
//! `render::radiosity`. Holds: the defaults are POV-Ray 3.7's (manual, "Radiosity").

/// How indirect diffuse light is gathered and cached (POV-Ray 3.7 defaults).
#[derive(Clone, Debug, PartialEq)]
pub struct RadiositySettings {
    /// Rays shot to gather one new sample (`count`, default 35).
    pub count: u32,
    /// Size of the direction pool rays are drawn from in turn (`count`'s second value;
    /// defaults to `count`).
    pub direction_pool: u32,
    /// Tolerated error before a new sample is gathered (`error_bound`, default 1.8).
    pub error_bound: f64,
    /// Diffuse bounces of indirect light (`recursion_limit`, default 2, at most 20).
    pub recursion_limit: u32,
    /// Scale of gathered light (`brightness`, default 1).
    pub brightness: f64,
    /// Share of gathered light turned grey (`gray_threshold`, default 0).
    pub gray_threshold: f64,
    /// Factor on `error_bound` during the pretrace (`low_error_factor`, default 0.5).
    pub low_error_factor: f64,
    /// Smallest reuse radius, as a fraction of the distance from the eye
    /// (`minimum_reuse`, default 0.015).
    pub minimum_reuse: f64,
    /// Largest reuse radius, as a fraction of the distance from the eye
    /// (`maximum_reuse`, default 0.2).
    pub maximum_reuse: f64,
    /// Least number of samples blended (`nearest_count`, default 5, at most 20).
    pub nearest_count: u32,
    /// Block size of the first pretrace pass, as a fraction of the image
    /// (`pretrace_start`, default 0.08).
    pub pretrace_start: f64,
    /// Block size of the last pretrace pass (`pretrace_end`, default 0.04).
    pub pretrace_end: f64,
    /// Gathering rays weaker than this are not traced (`adc_bailout`, default 0.01).
    pub adc_bailout: f64,
    /// The final render gathers new samples too (`always_sample`, default off).
    pub always_sample: bool,
    /// Gathered light brighter than this is scaled down to it (`max_sample`; not positive:
    /// no limit, the default).
    pub max_sample: f64,
    /// Perturbed normals orient the gathering (`normal`, default off).
    pub use_normal: bool,
    /// Gathering rays pass through media (`media`, default off).
    pub use_media: bool,
}

impl Default for RadiositySettings {
    fn default() -> Self {
        RadiositySettings {
            count: 35,
            direction_pool: 35,
            error_bound: 1.8,
            recursion_limit: 2,
            brightness: 1.0,
            gray_threshold: 0.0,
            low_error_factor: 0.5,
            minimum_reuse: 0.015,
            maximum_reuse: 0.2,
            nearest_count: 5,
            pretrace_start: 0.08,
            pretrace_end: 0.04,
            adc_bailout: 0.01,
            always_sample: false,
            max_sample: -1.0,
            use_normal: false,
            use_media: false,
        }
    }
}
