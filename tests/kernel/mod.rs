mod assembly;
mod form_factor;
