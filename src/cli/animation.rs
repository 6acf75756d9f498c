//! POV-Ray's animation loop: which frames to render, each frame's clock, and the frames'
//! file names.
//!
//! Rules measured with `povray` 3.7 (a scene that `#debug`s the identifiers):
//! - without `Final_Frame` there is one image: `clock` is `Clock` (default 0), `clock_on`
//!   is 1 only when `Clock` was given, `clock_delta`, `frame_number`, `initial_frame`,
//!   `final_frame`, `initial_clock` and `final_clock` are 0;
//! - with `Final_Frame=F` frames `I..=F` are rendered (`Initial_Frame` default 1, below 0
//!   read as 0), `clock = Ic + (n - I) * (Fc - Ic) / (F - I)` (`Initial_Clock`/`Final_Clock`
//!   default 0 and 1); cyclic animation divides by `F + 1 - I` and the scene sees
//!   `final_frame` = F + 1; `clock_delta` is the step between frames;
//! - a subset bound below 1 is a fraction of the animation: frame `floor(fraction * F)`;
//!   the start is at least `I`; an end before the start renders the start frame alone; an
//!   end after `F` renders past it with the clock extrapolated (as `povray` does);
//!   `Frame_Step` skips frames from the start;
//! - file names get the frame number zero-padded to the digits of the `final_frame` the
//!   scene sees (`scene01.png … scene24.png`; `scene1.png … scene3.png` for 3 frames).
//!
//! One difference: a single-frame animation (`F = I`) gets `clock = Initial_Clock` and
//! `clock_delta` 0, where `povray` divides by zero (clock NaN).

use super::povray_options::Settings;

/// The animation identifiers a frame's scene sees.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrameClock {
    pub clock: f64,
    pub clock_delta: f64,
    pub clock_on: bool,
    pub frame_number: i64,
    pub initial_frame: i64,
    pub final_frame: i64,
    pub initial_clock: f64,
    pub final_clock: f64,
}

/// The frames to render.
#[derive(Clone, Debug, PartialEq)]
pub struct Animation {
    /// One entry per frame to render, in order.
    pub frames: Vec<FrameClock>,
    /// Whether this is an animation (frame numbers go into file names).
    pub animated: bool,
    /// Digits of frame numbers in file names.
    pub digits: usize,
}

/// Most frames one run may render (a typo such as `+KFF1e9` must not loop for days).
pub const MAX_FRAMES: i64 = 1_000_000;

impl Animation {
    /// The animation the settings describe; `frames` (durer's `--frames A..B`, already a
    /// subset) overrides the subset options.
    pub fn plan(settings: &Settings) -> Result<Animation, String> {
        let Some(user_final) = settings.final_frame.filter(|&f| f != -1) else {
            let clock = settings.clock.unwrap_or(0.0);
            return Ok(Animation {
                frames: vec![FrameClock {
                    clock,
                    clock_delta: 0.0,
                    clock_on: settings.clock.is_some(),
                    frame_number: 0,
                    initial_frame: 0,
                    final_frame: 0,
                    initial_clock: 0.0,
                    final_clock: 0.0,
                }],
                animated: false,
                digits: 0,
            });
        };
        let initial = settings.initial_frame.unwrap_or(1).max(0);
        if user_final < initial {
            return Err(format!(
                "the final frame {user_final} comes before the initial frame {initial}"
            ));
        }
        let final_seen = if settings.cyclic {
            user_final + 1
        } else {
            user_final
        };
        let initial_clock = settings.initial_clock.unwrap_or(0.0);
        let final_clock = settings.final_clock.unwrap_or(1.0);
        let divisor = (final_seen - initial) as f64;
        let delta = if divisor > 0.0 {
            (final_clock - initial_clock) / divisor
        } else {
            0.0
        };
        let bound = |value: f64| -> i64 {
            if value < 1.0 {
                (value * user_final as f64).floor() as i64
            } else {
                value.floor() as i64
            }
        };
        let start = settings.subset_start.map_or(initial, bound).max(initial);
        let end = settings.subset_end.map_or(user_final, bound).max(start);
        if end - start >= MAX_FRAMES {
            return Err(format!(
                "frames {start} to {end} are more than {MAX_FRAMES} frames"
            ));
        }
        let step = i64::from(settings.frame_step.max(1));
        let frames = (start..=end)
            .step_by(step as usize)
            .map(|frame| FrameClock {
                clock: initial_clock + (frame - initial) as f64 * delta,
                clock_delta: delta,
                clock_on: true,
                frame_number: frame,
                initial_frame: initial,
                final_frame: final_seen,
                initial_clock,
                final_clock,
            })
            .collect();
        Ok(Animation {
            frames,
            animated: true,
            digits: final_seen.max(end).to_string().len().max(1),
        })
    }
}

/// The file name of a frame: `base` (the output name without its type's extension) with
/// the frame number zero-padded to `digits`, then `.extension`.
pub fn frame_file_name(base: &str, frame: Option<i64>, digits: usize, extension: &str) -> String {
    match frame {
        Some(number) => format!("{base}{number:0digits$}.{extension}"),
        None => format!("{base}.{extension}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn plan(edit: impl FnOnce(&mut Settings)) -> Animation {
        let mut settings = Settings::povray_defaults();
        edit(&mut settings);
        Animation::plan(&settings).unwrap()
    }

    fn clocks(animation: &Animation) -> Vec<(i64, f64)> {
        animation
            .frames
            .iter()
            .map(|f| (f.frame_number, (f.clock * 1e6).round() / 1e6))
            .collect()
    }

    #[test]
    fn still_image_and_clock_option() {
        let still = plan(|_| {});
        assert!(!still.animated);
        assert_eq!(still.frames[0].clock, 0.0);
        assert!(!still.frames[0].clock_on);
        let clocked = plan(|s| s.clock = Some(0.25));
        assert_eq!(clocked.frames[0].clock, 0.25);
        assert!(clocked.frames[0].clock_on);
        assert_eq!(clocked.frames[0].final_frame, 0);
    }

    // Each case below is a povray 3.7 run's #debug output.
    #[test]
    fn frames_and_clocks_as_povray() {
        let a = plan(|s| s.final_frame = Some(3));
        assert_eq!(clocks(&a), vec![(1, 0.0), (2, 0.5), (3, 1.0)]);
        assert_eq!(a.frames[0].clock_delta, 0.5);
        assert_eq!(a.digits, 1);
        let a = plan(|s| {
            s.final_frame = Some(3);
            s.initial_clock = Some(2.0);
            s.final_clock = Some(4.0);
        });
        assert_eq!(clocks(&a), vec![(1, 2.0), (2, 3.0), (3, 4.0)]);
    }

    #[test]
    fn cyclic_animation_sees_one_frame_more() {
        let a = plan(|s| {
            s.final_frame = Some(12);
            s.cyclic = true;
            s.subset_start = Some(3.0);
            s.subset_end = Some(5.0);
        });
        assert_eq!(clocks(&a), vec![(3, 0.166667), (4, 0.25), (5, 0.333333)]);
        assert_eq!(a.frames[0].final_frame, 13);
        let a = plan(|s| {
            s.final_frame = Some(9);
            s.cyclic = true;
            s.subset_start = Some(8.0);
        });
        assert_eq!(a.frames.len(), 2);
        assert_eq!(a.digits, 2, "padded to final_frame 10");
    }

    #[test]
    fn subsets_fractions_steps() {
        let a = plan(|s| {
            s.final_frame = Some(10);
            s.subset_start = Some(0.2);
            s.subset_end = Some(0.4);
        });
        assert_eq!(
            clocks(&a),
            vec![(2, 0.111111), (3, 0.222222), (4, 0.333333)]
        );
        let a = plan(|s| {
            s.initial_frame = Some(5);
            s.final_frame = Some(10);
            s.subset_start = Some(0.5);
        });
        assert_eq!(a.frames.len(), 6);
        assert_eq!(a.frames[0].frame_number, 5);
        let a = plan(|s| {
            s.final_frame = Some(10);
            s.frame_step = 3;
        });
        let numbers: Vec<i64> = a.frames.iter().map(|f| f.frame_number).collect();
        assert_eq!(numbers, vec![1, 4, 7, 10]);
        let a = plan(|s| {
            s.final_frame = Some(10);
            s.subset_start = Some(4.0);
            s.subset_end = Some(3.0);
        });
        assert_eq!(clocks(&a), vec![(4, 0.333333)]);
        let a = plan(|s| {
            s.final_frame = Some(10);
            s.subset_start = Some(10.0);
            s.subset_end = Some(11.0);
        });
        assert_eq!(clocks(&a), vec![(10, 1.0), (11, 1.111111)]);
        let a = plan(|s| {
            s.final_frame = Some(10);
            s.subset_end = Some(1.0);
        });
        assert_eq!(a.frames.len(), 1, "1.0 is frame 1, not a fraction");
    }

    #[test]
    fn single_frame_animation_has_a_finite_clock() {
        let a = plan(|s| s.final_frame = Some(1));
        assert_eq!(a.frames[0].clock, 0.0);
        assert_eq!(a.frames[0].clock_delta, 0.0);
    }

    #[test]
    fn file_names_are_zero_padded() {
        assert_eq!(frame_file_name("scene", Some(1), 2, "png"), "scene01.png");
        assert_eq!(
            frame_file_name("scene", Some(100), 3, "png"),
            "scene100.png"
        );
        assert_eq!(frame_file_name("a.b", None, 0, "tga"), "a.b.tga");
    }
}
