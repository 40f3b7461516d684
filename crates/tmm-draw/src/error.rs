//! Errors of the drawing model (ошибки модели чертежа): a value a GOST rule
//! does not allow is refused when the element is made, never drawn.

/// What a drawing element was refused for.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DrawError {
    /// A scale outside the GOST 2.302 series.
    #[error("scale {paper}:{real} is not a GOST 2.302 scale (valid: {valid})")]
    Scale {
        /// Paper part of the ratio.
        paper: f64,
        /// Real (model) part of the ratio.
        real: f64,
        /// The allowed scales, as a list to show.
        valid: String,
    },
    /// A main-line thickness outside GOST 2.303's 0.5 … 1.4 mm.
    #[error("main line thickness s = {0} mm is outside GOST 2.303's 0.5 … 1.4 mm")]
    Thickness(f64),
    /// A letter height outside the GOST 2.304 series.
    #[error("letter height {0} mm is not a GOST 2.304 size (valid: 2.5, 3.5, 5, 7, 10, 14, 20 mm)")]
    TextHeight(f64),
    /// A coordinate or length that is not a finite number.
    #[error("{0} is not a finite number")]
    NotFinite(&'static str),
    /// A geometric element that cannot be drawn (a zero radius, too few points).
    #[error("{0}")]
    Degenerate(&'static str),
    /// A layer named by an element that the scene does not declare.
    #[error("layer {0:?} is not declared in the scene")]
    UnknownLayer(String),
    /// Rich-text markup with an unclosed group.
    #[error("text {0:?}: unclosed '{{' in a sub- or superscript")]
    Markup(String),
}
