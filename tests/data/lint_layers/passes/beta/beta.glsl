// A shader helper of pass beta.
