//! POV-Ray 3.7's render options: `+`/`-` switches and `.ini` files, read into [`Settings`].
//!
//! In: command-line words and `.ini` files, in order. Out: one [`Settings`], later options
//! overriding earlier ones (`Library_Path`/`+L` and `Declare` accumulate), as POV-Ray
//! documents. Holds: every switch and key of POV-Ray 3.7's reference (r3_2) is known; an
//! unknown one is an error naming the nearest known one (POV-Ray itself silently ignores
//! most unknown switches). Options that change nothing in durer's output (display, preview,
//! bounding, block order) are accepted silently; options whose effect durer lacks are
//! accepted with a warning ([`Settings::warnings`]).
//!
//! Switches are case-insensitive; a switch that toggles takes `+` for on and `-` for off,
//! one that sets a value takes either sign. INI lines are `Key=value ; comment`, or switches,
//! or the name of another INI file (nested at most ten deep); `[Section]` labels select parts
//! of a file (`scene.ini[High]`; without a label only the part before the first label is
//! read). Values may be quoted with `"` or `'`.

use std::path::{Path, PathBuf};

/// Deepest nesting of INI files within INI files, as POV-Ray allows.
const MAX_INI_DEPTH: usize = 10;

pub use durer::render::output::FileFormat as FileType;

/// Which text streams are shown on the console (`+GD +GF +GR +GS +GW`, `+GA` for all).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Streams {
    /// `#debug` output.
    pub debug: bool,
    /// Fatal errors.
    pub fatal: bool,
    /// Render progress.
    pub render: bool,
    /// Statistics at the end.
    pub statistics: bool,
    /// Warnings.
    pub warning: bool,
}

impl Default for Streams {
    fn default() -> Streams {
        Streams {
            debug: true,
            fatal: true,
            render: true,
            statistics: true,
            warning: true,
        }
    }
}

/// Every option's value after reading the command line and INI files.
#[derive(Clone, Debug, PartialEq)]
pub struct Settings {
    pub input: Option<PathBuf>,
    /// `Output_File_Name` as given (`-` for standard output; a name ending in `/` is a folder).
    pub output: Option<String>,
    pub output_to_file: bool,
    /// The type named by `+F`/`Output_File_Type`, if any.
    pub file_type: Option<FileType>,
    pub bits_per_colour: Option<u32>,
    pub alpha: bool,
    /// JPEG quality (`Compression`), 2..=100 (0 and 1 mean the default, 85).
    pub compression: Option<u32>,
    pub width: u32,
    pub height: u32,
    pub start_column: Option<f64>,
    pub end_column: Option<f64>,
    pub start_row: Option<f64>,
    pub end_row: Option<f64>,
    pub antialias: bool,
    pub antialias_threshold: f64,
    pub sampling_method: u32,
    pub antialias_depth: u32,
    pub jitter: bool,
    pub jitter_amount: f64,
    pub antialias_gamma: f64,
    pub quality: u32,
    pub clock: Option<f64>,
    pub initial_frame: Option<i64>,
    pub final_frame: Option<i64>,
    pub initial_clock: Option<f64>,
    pub final_clock: Option<f64>,
    /// Frame number, or a fraction of the animation when below 1.
    pub subset_start: Option<f64>,
    pub subset_end: Option<f64>,
    pub frame_step: u32,
    pub cyclic: bool,
    pub library_paths: Vec<PathBuf>,
    /// `Declare=NAME=VALUE` (POV-Ray: floats) and durer's `--define` (any value), in order.
    pub declares: Vec<(String, String)>,
    pub include_header: Option<PathBuf>,
    pub version: Option<f64>,
    pub threads: Option<usize>,
    pub verbose: bool,
    pub streams: Streams,
    /// `Statistic_File`/`+GSfile`: where the statistics are also written.
    pub statistics_file: Option<PathBuf>,
    /// `File_Gamma`: `None` for sRGB (the default), else a power.
    pub file_gamma: Option<f64>,
    /// durer's `--limit`s.
    pub limits: durer::limits::Limits,
    /// Which files the scene may read and write (`--allow-read`, `--file-policy` ...).
    pub file_policy: durer::file_policy::FilePolicy,
    /// `Warning_Level` 0..=10 (0: no warnings).
    pub warning_level: u32,
    /// Accepted options whose effect durer does not have, one message each.
    pub warnings: Vec<String>,
}

impl Settings {
    /// POV-Ray 3.7's built-in defaults (before any INI file).
    pub fn povray_defaults() -> Settings {
        Settings {
            input: None,
            output: None,
            output_to_file: true,
            file_type: None,
            bits_per_colour: None,
            alpha: false,
            compression: None,
            width: 160,
            height: 120,
            start_column: None,
            end_column: None,
            start_row: None,
            end_row: None,
            antialias: false,
            antialias_threshold: 0.3,
            sampling_method: 1,
            antialias_depth: 3,
            jitter: true,
            jitter_amount: 1.0,
            antialias_gamma: 2.5,
            quality: 9,
            clock: None,
            initial_frame: None,
            final_frame: None,
            initial_clock: None,
            final_clock: None,
            subset_start: None,
            subset_end: None,
            frame_step: 1,
            cyclic: false,
            library_paths: Vec::new(),
            declares: Vec::new(),
            include_header: None,
            version: None,
            threads: None,
            verbose: false,
            streams: Streams::default(),
            statistics_file: None,
            file_gamma: None,
            warning_level: 10,
            limits: durer::limits::Limits::default(),
            file_policy: durer::file_policy::FilePolicy::default(),
            warnings: Vec::new(),
        }
    }
}

/// How an option's text after the switch letters or `=` is read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    /// On/off: `+X`/`-X`, `Key=on`.
    Toggle,
    /// On/off with an optional number (`+A0.3`, `+J0.5`): a number sets the value and,
    /// under `+`, turns the option on.
    ToggleNumber,
    /// A value that must be given.
    Value,
    /// On/off with an optional file name (`+GSfile`, `Statistic_File=true|file`).
    ToggleFile,
    /// Takes any value or none; accepted and without effect in durer.
    Anything,
}

/// What an option sets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Id {
    Input,
    Output,
    OutputToFile,
    FileType,
    Alpha,
    BitsPerColour,
    Compression,
    Width,
    Height,
    StartColumn,
    EndColumn,
    StartRow,
    EndRow,
    Antialias,
    AntialiasThreshold,
    SamplingMethod,
    AntialiasDepth,
    Jitter,
    JitterAmount,
    AntialiasGamma,
    Quality,
    Clock,
    InitialFrame,
    FinalFrame,
    InitialClock,
    FinalClock,
    SubsetStart,
    SubsetEnd,
    FrameStep,
    Cyclic,
    LibraryPath,
    Declare,
    IncludeHeader,
    Version,
    Threads,
    Verbose,
    AllConsole,
    DebugConsole,
    FatalConsole,
    RenderConsole,
    StatisticConsole,
    WarningConsole,
    StatisticFile,
    OtherStreamFile,
    FileGamma,
    WarningLevel,
    /// Changes nothing in durer's output: accepted silently.
    NoEffect,
    /// durer lacks the effect: accepted with a warning.
    Unsupported(&'static str),
}

/// One option: its INI key, its switch letters (if any), how its value is read.
struct OptionSpec {
    key: &'static str,
    switch: Option<&'static str>,
    kind: Kind,
    id: Id,
}

const fn spec(key: &'static str, switch: Option<&'static str>, kind: Kind, id: Id) -> OptionSpec {
    OptionSpec {
        key,
        switch,
        kind,
        id,
    }
}

const SHELL: &str = "durer does not run shell commands";

/// POV-Ray 3.7's options (reference section 3.2), each once.
const OPTIONS: &[OptionSpec] = &[
    // Animation.
    spec("Clock", Some("K"), Kind::Value, Id::Clock),
    spec("Initial_Frame", Some("KFI"), Kind::Value, Id::InitialFrame),
    spec("Final_Frame", Some("KFF"), Kind::Value, Id::FinalFrame),
    spec("Initial_Clock", Some("KI"), Kind::Value, Id::InitialClock),
    spec("Final_Clock", Some("KF"), Kind::Value, Id::FinalClock),
    spec(
        "Subset_Start_Frame",
        Some("SF"),
        Kind::Value,
        Id::SubsetStart,
    ),
    spec("Subset_End_Frame", Some("EF"), Kind::Value, Id::SubsetEnd),
    spec("Frame_Step", Some("STP"), Kind::Value, Id::FrameStep),
    spec("Cyclic_Animation", Some("KC"), Kind::Toggle, Id::Cyclic),
    spec(
        "Field_Render",
        Some("UF"),
        Kind::Toggle,
        Id::Unsupported("field rendering is not supported: whole frames are rendered"),
    ),
    spec(
        "Odd_Field",
        Some("UO"),
        Kind::Toggle,
        Id::Unsupported("field rendering is not supported: whole frames are rendered"),
    ),
    // Output size and region.
    spec("Height", Some("H"), Kind::Value, Id::Height),
    spec("Width", Some("W"), Kind::Value, Id::Width),
    spec(
        "Max_Image_Buffer_Memory",
        Some("MI"),
        Kind::Value,
        Id::NoEffect,
    ),
    spec("Start_Column", Some("SC"), Kind::Value, Id::StartColumn),
    spec("Start_Row", Some("SR"), Kind::Value, Id::StartRow),
    spec("End_Column", Some("EC"), Kind::Value, Id::EndColumn),
    spec("End_Row", Some("ER"), Kind::Value, Id::EndRow),
    // Interrupting, resuming.
    spec("Test_Abort", Some("X"), Kind::ToggleNumber, Id::NoEffect),
    spec("Test_Abort_Count", None, Kind::Value, Id::NoEffect),
    spec(
        "Continue_Trace",
        Some("C"),
        Kind::Toggle,
        Id::Unsupported("`Continue_Trace` is not supported: the image is rendered whole"),
    ),
    spec(
        "Create_Ini",
        Some("GI"),
        Kind::ToggleFile,
        Id::Unsupported("`Create_Ini` is not supported: no INI file is written"),
    ),
    // Display (durer never opens a window).
    spec("Display", Some("D"), Kind::Anything, Id::NoEffect),
    spec("Video_Mode", None, Kind::Value, Id::NoEffect),
    spec("Palette", None, Kind::Value, Id::NoEffect),
    spec("Display_Gamma", None, Kind::Value, Id::NoEffect),
    spec("Pause_When_Done", Some("P"), Kind::Toggle, Id::NoEffect),
    spec("Verbose", Some("V"), Kind::Toggle, Id::Verbose),
    spec("Draw_Vistas", Some("UD"), Kind::Toggle, Id::NoEffect),
    spec("Preview_Start_Size", Some("SP"), Kind::Value, Id::NoEffect),
    spec("Preview_End_Size", Some("EP"), Kind::Value, Id::NoEffect),
    // File output.
    spec("Output_to_File", None, Kind::Toggle, Id::OutputToFile),
    spec("Output_File_Type", None, Kind::Value, Id::FileType),
    spec("Output_Alpha", Some("UA"), Kind::Toggle, Id::Alpha),
    spec("Bits_Per_Color", None, Kind::Value, Id::BitsPerColour),
    spec("Bits_Per_Colour", None, Kind::Value, Id::BitsPerColour),
    spec("Compression", None, Kind::Value, Id::Compression),
    spec("Output_File_Name", Some("O"), Kind::Value, Id::Output),
    spec("Dither", Some("DF"), Kind::Toggle, Id::NoEffect),
    spec("Dither_Method", None, Kind::Value, Id::NoEffect),
    spec("File_Gamma", None, Kind::Value, Id::FileGamma),
    spec("Histogram_Type", None, Kind::Value, Id::NoEffect),
    spec("Histogram_Name", None, Kind::Value, Id::NoEffect),
    spec("Histogram_Grid_Size", None, Kind::Value, Id::NoEffect),
    // Scene parsing.
    spec("Declare", None, Kind::Value, Id::Declare),
    spec("Input_File_Name", Some("I"), Kind::Value, Id::Input),
    spec("Include_Header", Some("HI"), Kind::Value, Id::IncludeHeader),
    spec("Library_Path", Some("L"), Kind::Value, Id::LibraryPath),
    spec("Version", Some("MV"), Kind::Value, Id::Version),
    // Shell-out commands.
    spec(
        "Pre_Scene_Command",
        None,
        Kind::Value,
        Id::Unsupported(SHELL),
    ),
    spec(
        "Pre_Frame_Command",
        None,
        Kind::Value,
        Id::Unsupported(SHELL),
    ),
    spec(
        "Post_Scene_Command",
        None,
        Kind::Value,
        Id::Unsupported(SHELL),
    ),
    spec(
        "Post_Frame_Command",
        None,
        Kind::Value,
        Id::Unsupported(SHELL),
    ),
    spec(
        "User_Abort_Command",
        None,
        Kind::Value,
        Id::Unsupported(SHELL),
    ),
    spec(
        "Fatal_Error_Command",
        None,
        Kind::Value,
        Id::Unsupported(SHELL),
    ),
    spec("Pre_Scene_Return", None, Kind::Value, Id::NoEffect),
    spec("Pre_Frame_Return", None, Kind::Value, Id::NoEffect),
    spec("Post_Scene_Return", None, Kind::Value, Id::NoEffect),
    spec("Post_Frame_Return", None, Kind::Value, Id::NoEffect),
    spec("User_Abort_Return", None, Kind::Value, Id::NoEffect),
    spec("Fatal_Error_Return", None, Kind::Value, Id::NoEffect),
    // Text streams.
    spec("All_Console", Some("GA"), Kind::ToggleFile, Id::AllConsole),
    spec(
        "Debug_Console",
        Some("GD"),
        Kind::ToggleFile,
        Id::DebugConsole,
    ),
    spec(
        "Fatal_Console",
        Some("GF"),
        Kind::ToggleFile,
        Id::FatalConsole,
    ),
    spec(
        "Render_Console",
        Some("GR"),
        Kind::ToggleFile,
        Id::RenderConsole,
    ),
    spec(
        "Statistic_Console",
        Some("GS"),
        Kind::ToggleFile,
        Id::StatisticConsole,
    ),
    spec(
        "Warning_Console",
        Some("GW"),
        Kind::ToggleFile,
        Id::WarningConsole,
    ),
    spec("All_File", None, Kind::ToggleFile, Id::OtherStreamFile),
    spec("Debug_File", None, Kind::ToggleFile, Id::OtherStreamFile),
    spec("Fatal_File", None, Kind::ToggleFile, Id::OtherStreamFile),
    spec("Render_File", None, Kind::ToggleFile, Id::OtherStreamFile),
    spec("Statistic_File", None, Kind::ToggleFile, Id::StatisticFile),
    spec("Warning_File", None, Kind::ToggleFile, Id::OtherStreamFile),
    spec("Append_File", Some("GP"), Kind::Toggle, Id::NoEffect),
    spec("Warning_Level", Some("WL"), Kind::Value, Id::WarningLevel),
    // Tracing.
    spec("Work_Threads", Some("WT"), Kind::Value, Id::Threads),
    spec("Render_Block_Size", Some("BS"), Kind::Value, Id::NoEffect),
    spec("Render_Pattern", Some("RP"), Kind::Value, Id::NoEffect),
    spec("Render_Block_Step", Some("RS"), Kind::Value, Id::NoEffect),
    spec("Quality", Some("Q"), Kind::Value, Id::Quality),
    spec("Bounding", Some("MB"), Kind::ToggleNumber, Id::NoEffect),
    spec("Bounding_Threshold", None, Kind::Value, Id::NoEffect),
    spec("Bounding_Method", Some("BM"), Kind::Value, Id::NoEffect),
    spec("Light_Buffer", Some("UL"), Kind::Toggle, Id::NoEffect),
    spec("Vista_Buffer", Some("UV"), Kind::Toggle, Id::NoEffect),
    spec("Remove_Bounds", Some("UR"), Kind::Toggle, Id::NoEffect),
    spec("Split_Unions", Some("SU"), Kind::Toggle, Id::NoEffect),
    // Anti-aliasing.
    spec("Antialias", Some("A"), Kind::ToggleNumber, Id::Antialias),
    spec(
        "Sampling_Method",
        Some("AM"),
        Kind::Value,
        Id::SamplingMethod,
    ),
    spec(
        "Antialias_Threshold",
        None,
        Kind::Value,
        Id::AntialiasThreshold,
    ),
    spec("Jitter", Some("J"), Kind::ToggleNumber, Id::Jitter),
    spec("Jitter_Amount", None, Kind::Value, Id::JitterAmount),
    spec(
        "Antialias_Depth",
        Some("R"),
        Kind::Value,
        Id::AntialiasDepth,
    ),
    spec(
        "Antialias_Gamma",
        Some("AG"),
        Kind::Value,
        Id::AntialiasGamma,
    ),
    // Radiosity.
    spec(
        "High_Reproducibility",
        Some("HR"),
        Kind::Toggle,
        Id::NoEffect,
    ),
    spec(
        "Radiosity_File_Name",
        Some("RF"),
        Kind::Value,
        Id::Unsupported("radiosity sample files are not supported: samples are computed afresh"),
    ),
    spec(
        "Radiosity_From_File",
        Some("RFI"),
        Kind::Toggle,
        Id::Unsupported("radiosity sample files are not supported: samples are computed afresh"),
    ),
    spec(
        "Radiosity_To_File",
        Some("RFO"),
        Kind::Toggle,
        Id::Unsupported("radiosity sample files are not supported: samples are computed afresh"),
    ),
    spec(
        "Radiosity_Vain_Pretrace",
        Some("RVP"),
        Kind::Toggle,
        Id::NoEffect,
    ),
];

/// Where an option was read, for messages.
#[derive(Clone, Debug)]
pub struct Origin {
    /// `command line`, or the INI file's path and line.
    pub place: String,
}

/// A mistake in the options.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct OptionError(pub String);

impl std::fmt::Display for OptionError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

/// Reads options into settings.
pub struct OptionReader {
    pub settings: Settings,
    /// INI files being read, innermost last (for nesting depth and cycles).
    open_files: Vec<PathBuf>,
}

/// The words a switch word is made of: sign, letters-and-value.
fn split_sign(word: &str) -> Option<(bool, &str)> {
    if let Some(rest) = word.strip_prefix('+') {
        Some((true, rest))
    } else {
        word.strip_prefix('-').map(|rest| (false, rest))
    }
}

/// Removes one pair of matching quotes around `text`.
fn unquote(text: &str) -> &str {
    let text = text.trim();
    for quote in ['"', '\''] {
        if text.len() >= 2 && text.starts_with(quote) && text.ends_with(quote) {
            return &text[1..text.len() - 1];
        }
    }
    text
}

/// An INI boolean: `true yes on 1` or `false no off 0`.
fn parse_bool(text: &str) -> Option<bool> {
    match text.trim().to_ascii_lowercase().as_str() {
        "true" | "yes" | "on" | "1" => Some(true),
        "false" | "no" | "off" | "0" => Some(false),
        _ => None,
    }
}

fn parse_number(text: &str) -> Option<f64> {
    let text = text.trim();
    // POV-Ray reads `.5` and `0.5`; Rust's parser does too, but not a leading `+`.
    let value: f64 = text.strip_prefix('+').unwrap_or(text).parse().ok()?;
    value.is_finite().then_some(value)
}

/// Whether `word` names an INI file: `name.ini`, `name.ini[Section]`, `name[Section]`.
pub fn looks_like_ini(word: &str) -> bool {
    let (file, _) = split_section(word);
    file.to_ascii_lowercase().ends_with(".ini") || word.ends_with(']')
}

/// Whether `word` is an INI option written on the command line: `Key=value` with a key
/// made of letters and underscores.
pub fn looks_like_key(word: &str) -> bool {
    word.split_once('=').is_some_and(|(key, _)| {
        !key.is_empty() && key.chars().all(|c| c.is_ascii_alphabetic() || c == '_')
    })
}

/// `file[Section]` into the file and the section label.
fn split_section(word: &str) -> (&str, Option<&str>) {
    if let Some(open) = word.rfind('[') {
        if word.ends_with(']') && open > 0 {
            return (&word[..open], Some(&word[open + 1..word.len() - 1]));
        }
    }
    (word, None)
}

impl OptionReader {
    pub fn new(settings: Settings) -> OptionReader {
        OptionReader {
            settings,
            open_files: Vec::new(),
        }
    }

    /// Reads one `+`/`-` switch word (`+W320`, `-GA`, `+Ifile.pov`).
    pub fn switch(&mut self, word: &str, origin: &Origin) -> Result<(), OptionError> {
        let Some((plus, body)) = split_sign(word) else {
            return Err(OptionError(format!(
                "{}: `{word}` is not a switch",
                origin.place
            )));
        };
        // +F is special: a type letter and a bit depth follow.
        if let Some(rest) = body.strip_prefix(['F', 'f']) {
            return self.file_type_switch(plus, rest, word, origin);
        }
        let upper = body.to_ascii_uppercase();
        // The longest switch whose letters start the word and whose value fits.
        let mut candidates: Vec<&OptionSpec> = OPTIONS
            .iter()
            .filter(|o| o.switch.is_some_and(|s| upper.starts_with(s)))
            .collect();
        candidates.sort_by_key(|o| std::cmp::Reverse(o.switch.map_or(0, str::len)));
        let mut first_error = None;
        for option in candidates {
            let letters = option.switch.map_or(0, str::len);
            let value = &body[letters..];
            // Letters after the switch of a numeric option mean another, unknown switch
            // (`+WX3` is not `+W` with the value `X3`).
            let takes_text = matches!(option.kind, Kind::ToggleFile | Kind::Anything)
                || matches!(
                    option.id,
                    Id::Input
                        | Id::Output
                        | Id::LibraryPath
                        | Id::IncludeHeader
                        | Id::Unsupported(_)
                );
            if !takes_text && value.starts_with(|c: char| c.is_ascii_alphabetic()) {
                continue;
            }
            match self.apply(option, plus, Some(value), true, origin) {
                Ok(()) => return Ok(()),
                Err(error) => {
                    first_error.get_or_insert(error);
                }
            }
        }
        Err(first_error.unwrap_or_else(|| {
            let letters: String = body
                .chars()
                .take_while(|c| c.is_ascii_alphabetic())
                .collect();
            let switches = OPTIONS.iter().filter_map(|o| o.switch);
            let hint = durer::diag::did_you_mean(&letters.to_ascii_uppercase(), switches)
                .map(|s| format!(" (did you mean `{}{s}`?)", if plus { '+' } else { '-' }))
                .unwrap_or_default();
            OptionError(format!(
                "{}: unknown switch `{word}`{hint}; POV-Ray would ignore it silently, durer \
                 refuses it so a typo is not lost",
                origin.place
            ))
        }))
    }

    /// `+F[type][bits]` / `-F...`: file output on or off, and its type and depth.
    fn file_type_switch(
        &mut self,
        plus: bool,
        rest: &str,
        word: &str,
        origin: &Origin,
    ) -> Result<(), OptionError> {
        self.settings.output_to_file = plus;
        let mut chars = rest.chars();
        let Some(letter) = chars.next() else {
            return Ok(());
        };
        let Some(file_type) = FileType::from_letter(letter) else {
            return Err(OptionError(format!(
                "{}: `{word}`: unknown file type `{letter}` (one of N P T C B J E H S)",
                origin.place
            )));
        };
        self.settings.file_type = Some(file_type);
        let bits = chars.as_str();
        if !bits.is_empty() {
            self.set_bits(bits, word, origin)?;
        }
        Ok(())
    }

    fn set_bits(&mut self, text: &str, word: &str, origin: &Origin) -> Result<(), OptionError> {
        match text.trim().parse::<u32>() {
            Ok(bits) if (1..=16).contains(&bits) => {
                self.settings.bits_per_colour = Some(bits.clamp(5, 16));
                Ok(())
            }
            _ => Err(OptionError(format!(
                "{}: `{word}`: bits per colour must be a whole number from 5 to 16",
                origin.place
            ))),
        }
    }

    /// Reads an INI `Key=value` (the key in any case).
    pub fn key(&mut self, key: &str, value: &str, origin: &Origin) -> Result<(), OptionError> {
        let key = key.trim();
        let Some(option) = OPTIONS.iter().find(|o| o.key.eq_ignore_ascii_case(key)) else {
            // Input_File (without _Name) is accepted by POV-Ray and shown in its manual.
            if key.eq_ignore_ascii_case("Input_File") {
                return self.key("Input_File_Name", value, origin);
            }
            if key.eq_ignore_ascii_case("Output_File") {
                return self.key("Output_File_Name", value, origin);
            }
            let hint = durer::diag::did_you_mean(key, OPTIONS.iter().map(|o| o.key))
                .map(|k| format!(" (did you mean `{k}`?)"))
                .unwrap_or_default();
            return Err(OptionError(format!(
                "{}: unknown option `{key}`{hint}; POV-Ray would ignore it silently, durer \
                 refuses it so a typo is not lost",
                origin.place
            )));
        };
        self.apply(option, true, Some(value), false, origin)
    }

    /// Applies one option. `plus` is the switch's sign (true for INI keys); `switch` says
    /// whether `value` is what follows switch letters (empty when none) or an INI value.
    fn apply(
        &mut self,
        option: &OptionSpec,
        plus: bool,
        value: Option<&str>,
        switch: bool,
        origin: &Origin,
    ) -> Result<(), OptionError> {
        let raw = value.unwrap_or("");
        let text = unquote(raw);
        let name = if switch {
            format!(
                "{}{}",
                if plus { '+' } else { '-' },
                option.switch.unwrap_or("")
            )
        } else {
            option.key.to_string()
        };
        let bad = |what: &str| {
            OptionError(format!(
                "{}: `{name}{}{raw}`: {what}",
                origin.place,
                if switch { "" } else { "=" }
            ))
        };
        // The on/off state and the value the option carries.
        let (on, value): (bool, Option<&str>) = match option.kind {
            Kind::Toggle => {
                if switch {
                    if !text.is_empty() {
                        return Err(bad("this switch takes no value"));
                    }
                    (plus, None)
                } else {
                    (
                        parse_bool(text).ok_or_else(|| bad("expected on or off"))?,
                        None,
                    )
                }
            }
            Kind::ToggleNumber => {
                if switch {
                    if text.is_empty() {
                        (plus, None)
                    } else {
                        parse_number(text).ok_or_else(|| bad("expected a number"))?;
                        (plus, Some(text))
                    }
                } else if let Some(on) = parse_bool(text) {
                    (on, None)
                } else {
                    parse_number(text).ok_or_else(|| bad("expected on, off or a number"))?;
                    (true, Some(text))
                }
            }
            Kind::ToggleFile => {
                if switch {
                    (plus, (!text.is_empty()).then_some(text))
                } else if let Some(on) = parse_bool(text) {
                    (on, None)
                } else {
                    (true, (!text.is_empty()).then_some(text))
                }
            }
            Kind::Value => {
                if text.is_empty() {
                    return Err(bad("a value is needed"));
                }
                (plus, Some(text))
            }
            Kind::Anything => (plus, (!text.is_empty()).then_some(text)),
        };
        let number = || {
            value
                .and_then(parse_number)
                .ok_or_else(|| bad("expected a number"))
        };
        let whole = |low: f64, high: f64| -> Result<f64, OptionError> {
            let n = number()?;
            if n.fract() != 0.0 || n < low || n > high {
                return Err(bad(&format!(
                    "expected a whole number from {low} to {high}"
                )));
            }
            Ok(n)
        };
        let s = &mut self.settings;
        match option.id {
            Id::Input => s.input = value.map(PathBuf::from),
            Id::Output => s.output = value.map(str::to_string),
            Id::OutputToFile => s.output_to_file = on,
            Id::FileType => {
                let text = value.unwrap_or("");
                let mut chars = text.chars();
                let letter = chars.next().unwrap_or(' ');
                s.file_type = Some(
                    FileType::from_letter(letter)
                        .ok_or_else(|| bad("unknown file type (one of N P T C B J E H S)"))?,
                );
                let bits = chars.as_str();
                if !bits.is_empty() {
                    let word = format!("{name}={raw}");
                    return self.set_bits(bits, &word, origin);
                }
            }
            Id::Alpha => s.alpha = on,
            Id::BitsPerColour => {
                let word = format!("{name}={raw}");
                return self.set_bits(value.unwrap_or(""), &word, origin);
            }
            Id::Compression => s.compression = Some(number()?.clamp(0.0, 100.0) as u32),
            Id::Width => s.width = whole(1.0, 65535.0)? as u32,
            Id::Height => s.height = whole(1.0, 65535.0)? as u32,
            Id::StartColumn => s.start_column = Some(region_value(number()?, &bad)?),
            Id::EndColumn => s.end_column = Some(region_value(number()?, &bad)?),
            Id::StartRow => s.start_row = Some(region_value(number()?, &bad)?),
            Id::EndRow => s.end_row = Some(region_value(number()?, &bad)?),
            Id::Antialias => {
                s.antialias = on;
                if value.is_some() {
                    let threshold = number()?;
                    if !(0.0..=3.0).contains(&threshold) {
                        return Err(bad("the threshold must be from 0 to 3"));
                    }
                    s.antialias_threshold = threshold;
                }
            }
            Id::AntialiasThreshold => {
                let threshold = number()?;
                if !(0.0..=3.0).contains(&threshold) {
                    return Err(bad("the threshold must be from 0 to 3"));
                }
                s.antialias_threshold = threshold;
            }
            Id::SamplingMethod => s.sampling_method = whole(1.0, 2.0)? as u32,
            Id::AntialiasDepth => s.antialias_depth = whole(1.0, 9.0)? as u32,
            Id::Jitter => {
                s.jitter = on;
                if value.is_some() {
                    s.jitter_amount = jitter_amount(number()?, &bad)?;
                }
            }
            Id::JitterAmount => s.jitter_amount = jitter_amount(number()?, &bad)?,
            Id::AntialiasGamma => {
                let gamma = number()?;
                if gamma <= 0.0 {
                    return Err(bad("the gamma must be above 0"));
                }
                s.antialias_gamma = gamma;
            }
            Id::Quality => s.quality = whole(0.0, 11.0)? as u32,
            Id::Clock => s.clock = Some(number()?),
            Id::InitialFrame => s.initial_frame = Some(whole(-1e9, 1e9)? as i64),
            Id::FinalFrame => s.final_frame = Some(whole(-1e9, 1e9)? as i64),
            Id::InitialClock => s.initial_clock = Some(number()?),
            Id::FinalClock => s.final_clock = Some(number()?),
            Id::SubsetStart => s.subset_start = Some(number()?),
            Id::SubsetEnd => s.subset_end = Some(number()?),
            Id::FrameStep => s.frame_step = whole(1.0, 1e9)? as u32,
            Id::Cyclic => s.cyclic = on,
            Id::LibraryPath => s.library_paths.extend(value.map(PathBuf::from)),
            Id::Declare => {
                let text = value.unwrap_or("");
                let Some((identifier, expression)) = text.split_once('=') else {
                    return Err(bad("expected IDENTIFIER=VALUE"));
                };
                let identifier = identifier.trim();
                let valid = identifier
                    .chars()
                    .next()
                    .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
                    && identifier
                        .chars()
                        .all(|c| c.is_ascii_alphanumeric() || c == '_');
                if !valid {
                    return Err(bad("the name must be an identifier"));
                }
                // POV-Ray's Declare takes a float only.
                if parse_number(expression).is_none() {
                    return Err(bad(
                        "POV-Ray's Declare takes a float; use durer's --define NAME=EXPR for \
                         vectors, strings and expressions",
                    ));
                }
                s.declares
                    .push((identifier.to_string(), expression.trim().to_string()));
            }
            Id::IncludeHeader => s.include_header = value.map(PathBuf::from),
            Id::Version => {
                let version = number()?;
                s.version = Some(version);
            }
            Id::Threads => s.threads = Some(whole(1.0, 512.0)? as usize),
            Id::Verbose => s.verbose = on,
            Id::AllConsole => {
                s.streams = Streams {
                    debug: on,
                    fatal: on,
                    render: on,
                    statistics: on,
                    warning: on,
                };
                if value.is_some() {
                    s.warnings.push(format!(
                        "{}: `{name}{raw}`: text streams are not written to files (only \
                         statistics: Statistic_File)",
                        origin.place
                    ));
                }
            }
            Id::DebugConsole => s.streams.debug = on,
            Id::FatalConsole => s.streams.fatal = on,
            Id::RenderConsole => s.streams.render = on,
            Id::StatisticConsole => {
                s.streams.statistics = on;
                if let Some(file) = value {
                    s.statistics_file = Some(PathBuf::from(file));
                }
            }
            Id::WarningConsole => s.streams.warning = on,
            Id::StatisticFile => {
                s.statistics_file = match (on, value) {
                    (true, Some(file)) => Some(PathBuf::from(file)),
                    (true, None) => Some(PathBuf::from("statistics.out")),
                    (false, _) => None,
                }
            }
            Id::OtherStreamFile => {
                if on {
                    s.warnings.push(format!(
                        "{}: `{name}`: text streams are not written to files (only \
                         statistics: Statistic_File)",
                        origin.place
                    ));
                }
            }
            Id::FileGamma => {
                let text = value.unwrap_or("");
                s.file_gamma = if text.eq_ignore_ascii_case("srgb") {
                    None
                } else {
                    let gamma = number()?;
                    if gamma <= 0.0 {
                        return Err(bad("expected sRGB or a gamma above 0"));
                    }
                    Some(gamma)
                };
            }
            Id::WarningLevel => s.warning_level = whole(0.0, 10.0)? as u32,
            Id::NoEffect => {}
            Id::Unsupported(message) => {
                if on {
                    s.warnings
                        .push(format!("{}: `{name}`: {message}", origin.place));
                }
            }
        }
        Ok(())
    }

    /// Reads an INI file word from the command line or an INI line: `file`, `file.ini`,
    /// `file[Section]`; a name without extension gets `.ini` when that file exists.
    pub fn ini(&mut self, word: &str, origin: &Origin) -> Result<(), OptionError> {
        let (file, section) = split_section(word);
        let file = unquote(file);
        let mut path = PathBuf::from(file);
        if !path.exists() && Path::new(file).extension().is_none() {
            path = PathBuf::from(format!("{file}.ini"));
        }
        // INI files named inside INI files are found next to the file that names them.
        if path.is_relative() && !path.exists() {
            if let Some(parent) = self.open_files.last().and_then(|p| p.parent()) {
                let beside = parent.join(&path);
                if beside.exists() {
                    path = beside;
                }
            }
        }
        let text = std::fs::read(&path).map_err(|e| {
            OptionError(format!(
                "{}: cannot read INI file `{}`: {e}",
                origin.place,
                path.display()
            ))
        })?;
        let text = String::from_utf8_lossy(&text).into_owned();
        self.ini_text(&text, &path, section, origin)
    }

    /// Reads the text of INI file `path`, the part under `section` (or before any label).
    pub fn ini_text(
        &mut self,
        text: &str,
        path: &Path,
        section: Option<&str>,
        origin: &Origin,
    ) -> Result<(), OptionError> {
        if self.open_files.len() >= MAX_INI_DEPTH {
            return Err(OptionError(format!(
                "{}: INI files nested more than {MAX_INI_DEPTH} deep (at `{}`)",
                origin.place,
                path.display()
            )));
        }
        let canonical = path.canonicalize().unwrap_or_else(|_| path.to_path_buf());
        if self.open_files.contains(&canonical) {
            return Err(OptionError(format!(
                "{}: INI file `{}` includes itself",
                origin.place,
                path.display()
            )));
        }
        self.open_files.push(canonical);
        let result = self.ini_lines(text, path, section);
        self.open_files.pop();
        result
    }

    fn ini_lines(
        &mut self,
        text: &str,
        path: &Path,
        section: Option<&str>,
    ) -> Result<(), OptionError> {
        let mut reading = section.is_none();
        let mut found_section = section.is_none();
        for (number, line) in text.lines().enumerate() {
            let origin = Origin {
                place: format!("{}:{}", path.display(), number + 1),
            };
            let line = strip_comment(line).trim();
            if line.is_empty() {
                continue;
            }
            if line.starts_with('[') && line.ends_with(']') {
                let label = line[1..line.len() - 1].trim();
                reading = section.is_some_and(|s| s.trim().eq_ignore_ascii_case(label));
                found_section |= reading;
                continue;
            }
            if !reading {
                continue;
            }
            if line.starts_with('+') || line.starts_with('-') {
                // Switches; povray also takes `Key=value` and INI names among them
                // (its own splinefollow.ini: `+kf0.1666 +kff20 +kc declare=fp=0`).
                for word in split_words(line) {
                    if word.starts_with('+') || word.starts_with('-') {
                        self.switch(&word, &origin)?;
                    } else if let Some((key, value)) =
                        word.split_once('=').filter(|_| looks_like_key(&word))
                    {
                        self.key(key, value, &origin)?;
                    } else {
                        self.ini(&word, &origin)?;
                    }
                }
            } else if let Some((key, value)) = line.split_once('=') {
                self.key(key, value, &origin)?;
            } else {
                self.ini(line, &origin)?;
            }
        }
        if !found_section {
            return Err(OptionError(format!(
                "{}: no section [{}] in this INI file",
                path.display(),
                section.unwrap_or("")
            )));
        }
        Ok(())
    }
}

/// A region bound: a pixel number (from 1) or, between 0 and 1, a fraction of the size.
fn region_value(value: f64, bad: &dyn Fn(&str) -> OptionError) -> Result<f64, OptionError> {
    if value < 0.0 {
        return Err(bad("a region bound cannot be negative"));
    }
    Ok(value)
}

fn jitter_amount(value: f64, bad: &dyn Fn(&str) -> OptionError) -> Result<f64, OptionError> {
    if !(0.0..=1.0).contains(&value) {
        return Err(bad("the jitter amount must be from 0 to 1"));
    }
    Ok(value)
}

/// A line without its `;` comment (a `;` inside quotes is kept).
fn strip_comment(line: &str) -> &str {
    let mut quote = None;
    for (index, c) in line.char_indices() {
        match (quote, c) {
            (None, '"' | '\'') => quote = Some(c),
            (Some(q), c) if c == q => quote = None,
            (None, ';') => return &line[..index],
            _ => {}
        }
    }
    line
}

/// The switches of one INI line, split at blanks outside quotes.
fn split_words(line: &str) -> Vec<String> {
    let mut words = Vec::new();
    let mut current = String::new();
    let mut quote = None;
    for c in line.chars() {
        match (quote, c) {
            (None, '"' | '\'') => {
                quote = Some(c);
                current.push(c);
            }
            (Some(q), c) if c == q => {
                quote = None;
                current.push(c);
            }
            (None, c) if c.is_whitespace() => {
                if !current.is_empty() {
                    words.push(std::mem::take(&mut current));
                }
            }
            _ => current.push(c),
        }
    }
    if !current.is_empty() {
        words.push(current);
    }
    words
}

/// The INI files POV-Ray reads before the command line on Unix: `$POVINI`, else the first of
/// `./povray.ini`, `$HOME/.povray/3.7/povray.ini`, `/usr/local/etc/povray/3.7/povray.ini`,
/// `/etc/povray/3.7/povray.ini` that exists.
pub fn default_ini() -> Option<PathBuf> {
    if let Some(path) = std::env::var_os("POVINI") {
        return Some(PathBuf::from(path));
    }
    let mut candidates = vec![PathBuf::from("povray.ini")];
    if let Some(home) = std::env::var_os("HOME") {
        candidates.push(PathBuf::from(home).join(".povray/3.7/povray.ini"));
    }
    candidates.push(PathBuf::from("/usr/local/etc/povray/3.7/povray.ini"));
    candidates.push(PathBuf::from("/etc/povray/3.7/povray.ini"));
    candidates.into_iter().find(|path| path.is_file())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn here() -> Origin {
        Origin {
            place: "command line".into(),
        }
    }

    fn read(words: &[&str]) -> Result<Settings, OptionError> {
        let mut reader = OptionReader::new(Settings::povray_defaults());
        for word in words {
            reader.switch(word, &here())?;
        }
        Ok(reader.settings)
    }

    #[test]
    fn switches_set_their_values_in_any_case() {
        let s = read(&[
            "+W320",
            "-h240",
            "+Iscene.pov",
            "+oout.png",
            "+A0.1",
            "+am2",
            "+R4",
        ])
        .unwrap();
        assert_eq!((s.width, s.height), (320, 240));
        assert_eq!(s.input, Some(PathBuf::from("scene.pov")));
        assert_eq!(s.output.as_deref(), Some("out.png"));
        assert!(s.antialias);
        assert_eq!(s.antialias_threshold, 0.1);
        assert_eq!((s.sampling_method, s.antialias_depth), (2, 4));
    }

    #[test]
    fn longest_switch_letters_win() {
        let s = read(&["+KFI5", "+KFF10", "+KI0.5", "+KF2", "+K0.25", "+KC", "+WT3"]).unwrap();
        assert_eq!((s.initial_frame, s.final_frame), (Some(5), Some(10)));
        assert_eq!((s.initial_clock, s.final_clock), (Some(0.5), Some(2.0)));
        assert_eq!(s.clock, Some(0.25));
        assert!(s.cyclic);
        assert_eq!(s.threads, Some(3));
        assert_eq!(s.width, 160, "+WT is not +W");
        let s = read(&["+HIheader.inc", "+H77"]).unwrap();
        assert_eq!(s.include_header, Some(PathBuf::from("header.inc")));
        assert_eq!(s.height, 77);
    }

    #[test]
    fn toggles_follow_the_sign() {
        let s = read(&["+UA", "-J", "-GA", "+GS", "+D", "-V"]).unwrap();
        assert!(s.alpha && !s.jitter && !s.streams.warning && s.streams.statistics);
        let s = read(&["+A", "-A"]).unwrap();
        assert!(!s.antialias);
        assert!(read(&["+UA1"]).is_err(), "a toggle takes no value");
    }

    #[test]
    fn file_types_and_depths() {
        let s = read(&["+FN16"]).unwrap();
        assert_eq!(s.file_type, Some(FileType::Png));
        assert_eq!(s.bits_per_colour, Some(16));
        let s = read(&["+FC"]).unwrap();
        assert_eq!(s.file_type, Some(FileType::TgaCompressed));
        let s = read(&["-F"]).unwrap();
        assert!(!s.output_to_file);
        assert!(read(&["+FQ"]).is_err());
    }

    #[test]
    fn unknown_switches_name_the_nearest() {
        let error = read(&["+WX3"]).unwrap_err();
        assert!(error.0.contains("unknown switch `+WX3`"), "{error}");
        assert!(error.0.contains("did you mean `+W"), "{error}");
    }

    #[test]
    fn ini_sections_comments_and_later_wins() {
        let ini = "; resolution\n+W120 +H100 ; unlabelled\nAntialias=On\n[Low]\nWidth=80 ; c\n\
                   Height = 60\n[Really High]\nWidth='800'\n";
        let mut reader = OptionReader::new(Settings::povray_defaults());
        reader
            .ini_text(ini, Path::new("res.ini"), None, &here())
            .unwrap();
        assert_eq!((reader.settings.width, reader.settings.height), (120, 100));
        assert!(reader.settings.antialias);
        reader
            .ini_text(ini, Path::new("res.ini"), Some("low"), &here())
            .unwrap();
        assert_eq!((reader.settings.width, reader.settings.height), (80, 60));
        reader
            .ini_text(ini, Path::new("res.ini"), Some("really high"), &here())
            .unwrap();
        assert_eq!(reader.settings.width, 800);
        let error = reader
            .ini_text(ini, Path::new("res.ini"), Some("Huge"), &here())
            .unwrap_err();
        assert!(error.0.contains("no section [Huge]"), "{error}");
    }

    #[test]
    fn unknown_keys_name_the_nearest() {
        let mut reader = OptionReader::new(Settings::povray_defaults());
        let error = reader
            .ini_text("Widht=3\n", Path::new("a.ini"), None, &here())
            .unwrap_err();
        assert!(
            error.0.contains("a.ini:1: unknown option `Widht`"),
            "{error}"
        );
        assert!(error.0.contains("did you mean `Width`?"), "{error}");
    }

    #[test]
    fn declare_takes_floats_and_library_paths_accumulate() {
        let mut reader = OptionReader::new(Settings::povray_defaults());
        let ini = "Declare=Size=2.5\nLibrary_Path=/a\nLibrary_Path=\"/b c\"\n+L/d\n";
        reader
            .ini_text(ini, Path::new("a.ini"), None, &here())
            .unwrap();
        assert_eq!(
            reader.settings.declares,
            vec![("Size".into(), "2.5".into())]
        );
        assert_eq!(reader.settings.library_paths.len(), 3);
        assert_eq!(reader.settings.library_paths[1], PathBuf::from("/b c"));
        let error = reader
            .ini_text("Declare=V=<1,2>\n", Path::new("a.ini"), None, &here())
            .unwrap_err();
        assert!(error.0.contains("--define"), "{error}");
    }

    #[test]
    fn ignored_and_unsupported_options() {
        let s = read(&["+D", "-P", "+MB3", "+UR", "+BS16"]).unwrap();
        assert!(s.warnings.is_empty());
        let s = read(&["+UF"]).unwrap();
        assert_eq!(s.warnings.len(), 1);
        assert!(s.warnings[0].contains("field rendering"));
    }

    #[test]
    fn every_key_and_switch_is_listed_once() {
        let mut keys: Vec<String> = OPTIONS.iter().map(|o| o.key.to_ascii_lowercase()).collect();
        keys.sort();
        let count = keys.len();
        keys.dedup();
        assert_eq!(keys.len(), count);
        let mut switches: Vec<&str> = OPTIONS.iter().filter_map(|o| o.switch).collect();
        switches.sort();
        let count = switches.len();
        switches.dedup();
        assert_eq!(switches.len(), count);
    }
}
