mod assembly;
mod cells;
mod form_factor;
mod precision;
