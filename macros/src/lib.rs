//! The procedural macro of interfacial's ABI shell (docs/architecture.md, "Written
//! once, and the copies kept").
//!
//! [`with_twin`] writes an export's out-of-line twin and its argument view from the export's
//! own text, so the parameter list is written once in the source (where cbindgen, which expands
//! no macro, reads the export): the twin's list, the view's fields and both literals that build
//! the view are derived from it. [`with_view`] writes the view alone, for an export without a
//! twin.

use proc_macro::TokenStream as CompilerTokens;
use proc_macro2::TokenStream;
use quote::quote;
use syn::parse::{Parse, ParseStream};
use syn::punctuated::Punctuated;
use syn::{Attribute, FnArg, Ident, ItemFn, Pat, Stmt, Token, Type, braced, parenthesized};

/// An exported function that ends, when its body does not return, in a sibling call to a twin
/// with the identical parameter list (a jump that leaves the host's arguments where they are).
///
/// ```text
/// #[interfacial_macros::with_twin(
///     view = #[derive(Clone, Copy)] struct FricArgs as args,
///     unread = (ddpddh, slip),
///     twin = #[cold] #[inline(never)] unsafe extern "C" fn fric_general { args.general() },
/// )]
/// pub unsafe extern "C" fn fric_(lm: *mut c_int, /* … */) { /* fast path */ }
/// ```
///
/// expands to
///
/// - the view, `#[derive(Clone, Copy)] struct FricArgs { lm: *mut c_int, … }`: the view's
///   attributes, one private field per parameter but the `unread` ones, in the parameters'
///   order, name and type as in the signature;
/// - the export, attributes, signature and statements unchanged, with `let args = FricArgs {
///   lm, … };` (every field, by name) before its first statement and `unsafe { fric_general(lm,
///   …) }` (every parameter, in order) after its last;
/// - `fric_general`: the twin's attributes, the export's signature under the twin's name (not
///   exported, private), `let _ = (ddpddh, slip);`, the same `let args = FricArgs { … };`, then
///   the twin's statements.
///
/// Every parameter must be a plain name; each `unread` name must be a parameter. The twin is
/// written with the export's qualifiers (`unsafe extern "C" fn fric_general`), so that its
/// definition is found by searching for `fn fric_general`; other qualifiers are refused.
#[proc_macro_attribute]
pub fn with_twin(attr: CompilerTokens, item: CompilerTokens) -> CompilerTokens {
    emit(expand(attr.into(), item.into()))
}

/// [`with_twin`] without the twin, for an export whose whole body runs where the host called it:
///
/// ```text
/// #[interfacial_macros::with_view(view = struct CoefArgs as args, unread = (idata, rdata))]
/// pub unsafe extern "C" fn fric_coef_(fcoef: *mut f64, /* … */) { args.run(); }
/// ```
///
/// expands to the view (as [`with_twin`] writes it) and the export, attributes and signature
/// unchanged, its body `let _ = (idata, rdata);` (the unread parameters, named once), `let args
/// = CoefArgs { fcoef, … };`, then its statements.
#[proc_macro_attribute]
pub fn with_view(attr: CompilerTokens, item: CompilerTokens) -> CompilerTokens {
    emit(expand_view(attr.into(), item.into()))
}

/// The expansion handed back to the compiler, or its error as a `compile_error!` at the span
/// it names (both attributes).
fn emit(expanded: syn::Result<TokenStream>) -> CompilerTokens {
    expanded
        .unwrap_or_else(syn::Error::into_compile_error)
        .into()
}

/// The attribute's arguments.
struct Spec {
    view_attrs: Vec<Attribute>,
    view: Ident,
    binding: Ident,
    unread: Vec<Ident>,
    /// `None` when the attribute names no twin (`with_view`).
    twin: Option<Twin>,
}

/// The twin of [`with_twin`]: its attributes, qualifiers (as written), name and statements.
struct Twin {
    attrs: Vec<Attribute>,
    unsafety: Option<Token![unsafe]>,
    abi: Option<syn::Abi>,
    name: Ident,
    stmts: Vec<Stmt>,
}

/// Reads `key =`, naming the expected key when it is not there.
fn key(input: ParseStream, expected: &str) -> syn::Result<()> {
    let found: Ident = input.parse()?;
    if found != expected {
        return Err(syn::Error::new(
            found.span(),
            format!("with_twin: expected `{expected} = …` here"),
        ));
    }
    input.parse::<Token![=]>()?;
    Ok(())
}

impl Parse for Spec {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        key(input, "view")?;
        let view_attrs = Attribute::parse_outer(input)?;
        input.parse::<Token![struct]>()?;
        let view = input.parse()?;
        input.parse::<Token![as]>()?;
        let binding = input.parse()?;
        input.parse::<Token![,]>()?;

        key(input, "unread")?;
        let names;
        parenthesized!(names in input);
        let unread = Punctuated::<Ident, Token![,]>::parse_terminated(&names)?;
        let twin = if input.is_empty() {
            None
        } else {
            input.parse::<Token![,]>()?;
            if input.is_empty() {
                None
            } else {
                key(input, "twin")?;
                let attrs = Attribute::parse_outer(input)?;
                let unsafety = input.parse()?;
                let abi = input.parse()?;
                input.parse::<Token![fn]>()?;
                let name = input.parse()?;
                let body;
                braced!(body in input);
                let stmts = body.call(syn::Block::parse_within)?;
                if !input.is_empty() {
                    input.parse::<Token![,]>()?;
                }
                Some(Twin {
                    attrs,
                    unsafety,
                    abi,
                    name,
                    stmts,
                })
            }
        };
        Ok(Spec {
            view_attrs,
            view,
            binding,
            unread: unread.into_iter().collect(),
            twin,
        })
    }
}

/// The expansion of [`with_twin`], on `proc_macro2` streams (so the unit tests can run it).
fn expand(attr: TokenStream, item: TokenStream) -> syn::Result<TokenStream> {
    let spec: Spec = syn::parse2(attr)?;
    let export: ItemFn = syn::parse2(item)?;
    let Some(twin) = &spec.twin else {
        return Err(syn::Error::new(
            export.sig.ident.span(),
            "with_twin: expected `twin = …` after `unread`",
        ));
    };
    let view = View::of(&spec, &export, "with_twin")?;
    let View { item, build, .. } = &view;
    let sig = &export.sig;
    let names = view.params.iter().map(|(name, _)| name);
    let unread = &spec.unread;
    let Twin {
        attrs,
        unsafety,
        abi,
        name,
        stmts,
    } = twin;
    let written = quote! { #unsafety #abi fn };
    let export_prefix = {
        let (unsafety, abi) = (&sig.safety, &sig.abi);
        quote! { #unsafety #abi fn }
    };
    if written.to_string() != export_prefix.to_string() {
        return Err(syn::Error::new(
            name.span(),
            format!(
                "with_twin: write the twin as `{export_prefix} {name}`, the export's qualifiers"
            ),
        ));
    }
    let mut twin_sig = sig.clone();
    twin_sig.ident = name.clone();
    let export_attrs = &export.attrs;
    let vis = &export.vis;
    let export_stmts = &export.block.stmts;
    Ok(quote! {
        #item

        #(#export_attrs)*
        #vis #sig {
            #build
            #(#export_stmts)*
            unsafe { #name(#(#names),*) }
        }

        #(#attrs)*
        #[allow(clippy::too_many_arguments)]
        #twin_sig {
            let _ = (#(#unread,)*);
            #build
            #(#stmts)*
        }
    })
}

/// The expansion of [`with_view`], on `proc_macro2` streams.
fn expand_view(attr: TokenStream, item: TokenStream) -> syn::Result<TokenStream> {
    let spec: Spec = syn::parse2(attr)?;
    let export: ItemFn = syn::parse2(item)?;
    if let Some(twin) = &spec.twin {
        return Err(syn::Error::new(
            twin.name.span(),
            "with_view: takes no twin (see `with_twin`)",
        ));
    }
    let View { item, build, .. } = View::of(&spec, &export, "with_view")?;
    let unread = &spec.unread;
    let (attrs, vis, sig) = (&export.attrs, &export.vis, &export.sig);
    let stmts = &export.block.stmts;
    Ok(quote! {
        #item

        #(#attrs)*
        #vis #sig {
            let _ = (#(#unread,)*);
            #build
            #(#stmts)*
        }
    })
}

/// The argument view of an export, as both attributes write it.
struct View {
    /// Every parameter of the export, name and type, in order.
    params: Vec<(Ident, Type)>,
    /// The struct: the view's attributes, one private field per parameter but the unread ones.
    item: TokenStream,
    /// `let binding = View { field, … };`.
    build: TokenStream,
}

impl View {
    /// The view of `export`; `who` (the attribute's name) starts the messages.
    fn of(spec: &Spec, export: &ItemFn, who: &str) -> syn::Result<View> {
        let sig = &export.sig;
        if !sig.generics.params.is_empty() || sig.variadic.is_some() {
            return Err(syn::Error::new(
                sig.ident.span(),
                format!("{who}: the export must have no generics and no variadic part"),
            ));
        }
        let params = sig
            .inputs
            .iter()
            .map(|arg| match arg {
                FnArg::Typed(typed) => match &*typed.pat {
                    Pat::Ident(p) if p.by_ref.is_none() && p.subpat.is_none() => {
                        Ok((p.ident.clone(), (*typed.ty).clone()))
                    }
                    other => Err(syn::Error::new_spanned(
                        other,
                        format!("{who}: every parameter must be a plain name"),
                    )),
                },
                FnArg::Receiver(r) => Err(syn::Error::new_spanned(
                    r,
                    format!("{who}: the export cannot take `self`"),
                )),
            })
            .collect::<syn::Result<Vec<(Ident, Type)>>>()?;
        if let Some(stray) = spec
            .unread
            .iter()
            .find(|u| !params.iter().any(|(name, _)| name == *u))
        {
            return Err(syn::Error::new(
                stray.span(),
                format!(
                    "{who}: `{stray}` in `unread` is not a parameter of `{}`",
                    sig.ident
                ),
            ));
        }
        let (fields, types): (Vec<&Ident>, Vec<&Type>) = params
            .iter()
            .filter(|(name, _)| !spec.unread.contains(name))
            .map(|(name, ty)| (name, ty))
            .unzip();
        let Spec {
            view_attrs,
            view,
            binding,
            ..
        } = spec;
        let item = quote! {
            #(#view_attrs)*
            struct #view {
                #(#fields: #types,)*
            }
        };
        let build = quote! { let #binding = #view { #(#fields),* }; };
        Ok(View {
            params,
            item,
            build,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use quote::ToTokens;
    use syn::{Expr, File, Item, ItemStruct};

    fn export() -> TokenStream {
        quote! {
            /// Doc.
            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn ex_(a: *mut i32, b: *const f64, c: usize) {
                if fast(&v) { return; }
            }
        }
    }

    fn spec() -> TokenStream {
        quote! {
            view = #[derive(Clone, Copy)] struct View as v,
            unread = (b),
            twin = #[cold] unsafe extern "C" fn ex_twin { v.slow(); },
        }
    }

    /// The items of an expansion: the view, the export, the twin.
    fn items(out: TokenStream) -> (ItemStruct, ItemFn, ItemFn) {
        let file: File = syn::parse2(out).expect("the expansion parses as items");
        match <[Item; 3]>::try_from(file.items) {
            Ok([Item::Struct(view), Item::Fn(export), Item::Fn(twin)]) => (view, export, twin),
            _ => panic!("expected a struct and two functions"),
        }
    }

    /// The two functions of an expansion, export first.
    fn functions(out: TokenStream) -> (ItemFn, ItemFn) {
        let (_, export, twin) = items(out);
        (export, twin)
    }

    fn text<T: ToTokens>(t: &T) -> String {
        t.to_token_stream().to_string()
    }

    #[test]
    fn twin_has_the_exports_parameters_and_falls_through_to_it() {
        let (export, twin) = functions(expand(spec(), self::export()).unwrap());
        assert_eq!(export.sig.ident, "ex_");
        assert_eq!(twin.sig.ident, "ex_twin");
        // The same parameter list, ABI and safety; the twin is neither exported nor public.
        assert_eq!(text(&export.sig.inputs), text(&twin.sig.inputs));
        assert_eq!(text(&export.sig.abi), text(&twin.sig.abi));
        assert_eq!(text(&export.sig.safety), text(&twin.sig.safety));
        assert!(matches!(twin.vis, syn::Visibility::Inherited));
        let attrs = |f: &ItemFn| f.attrs.iter().map(text).collect::<Vec<_>>();
        assert_eq!(
            attrs(&twin),
            ["# [cold]", "# [allow (clippy :: too_many_arguments)]"]
        );
        assert_eq!(
            attrs(&export),
            ["# [doc = r\" Doc.\"]", "# [unsafe (no_mangle)]"]
        );
        // The export's last statement is the call to the twin with every parameter, in order.
        let last = export.block.stmts.last().unwrap();
        let Stmt::Expr(Expr::Unsafe(block), None) = last else {
            panic!("expected `unsafe {{ twin(..) }}` last, got {}", text(last));
        };
        assert_eq!(text(&block.block.stmts[0]), "ex_twin (a , b , c)");
    }

    #[test]
    fn view_has_a_field_per_read_parameter_with_its_type() {
        let (view, _, _) = items(expand(spec(), export()).unwrap());
        assert_eq!(view.ident, "View");
        assert!(matches!(view.vis, syn::Visibility::Inherited));
        assert_eq!(text(&view.attrs[0]), "# [derive (Clone , Copy)]");
        let fields: Vec<String> = view
            .fields
            .iter()
            .map(|f| {
                assert!(matches!(f.vis, syn::Visibility::Inherited));
                format!("{}: {}", text(&f.ident), text(&f.ty))
            })
            .collect();
        assert_eq!(fields, ["a: * mut i32", "c: usize"]);
    }

    #[test]
    fn view_is_built_from_the_read_parameters_in_both() {
        let (export, twin) = functions(expand(spec(), self::export()).unwrap());
        let view = "let v = View { a , c } ;";
        assert_eq!(text(&export.block.stmts[0]), view);
        // The twin names the unread parameters once (no unused-variable warning), then the view.
        assert_eq!(text(&twin.block.stmts[0]), "let _ = (b ,) ;");
        assert_eq!(text(&twin.block.stmts[1]), view);
        assert_eq!(text(&twin.block.stmts[2]), "v . slow () ;");
        // The export's own statement is kept between the view and the call.
        assert_eq!(export.block.stmts.len(), 3);
        assert!(text(&export.block.stmts[1]).starts_with("if fast"));
    }

    #[test]
    fn refuses_an_unread_name_that_is_not_a_parameter() {
        let spec =
            quote! { view = struct View as v, unread = (b, z), twin = unsafe extern "C" fn t { } };
        let err = expand(spec, export()).unwrap_err().to_string();
        assert_eq!(
            err,
            "with_twin: `z` in `unread` is not a parameter of `ex_`"
        );
    }

    #[test]
    fn refuses_a_parameter_that_is_not_a_plain_name() {
        let item = quote! { extern "C" fn ex_((a, b): (i32, i32)) {} };
        let spec =
            quote! { view = struct View as v, unread = (), twin = unsafe extern "C" fn t { } };
        let err = expand(spec, item).unwrap_err().to_string();
        assert_eq!(err, "with_twin: every parameter must be a plain name");
    }

    #[test]
    fn names_the_missing_key() {
        let spec = quote! { view = struct View as v, twin = unsafe extern "C" fn t { } };
        let err = expand(spec, export()).unwrap_err().to_string();
        assert_eq!(err, "with_twin: expected `unread = …` here");
    }

    #[test]
    fn view_alone_names_the_unread_then_builds_the_view() {
        let spec = quote! { view = struct View as v, unread = (b) };
        let file: File = syn::parse2(expand_view(spec, export()).unwrap()).unwrap();
        let Ok([Item::Struct(view), Item::Fn(export)]) = <[Item; 2]>::try_from(file.items) else {
            panic!("expected the view and the export");
        };
        assert_eq!(text(&view.fields), "{ a : * mut i32 , c : usize , }");
        assert_eq!(export.sig.ident, "ex_");
        let stmts: Vec<String> = export.block.stmts.iter().map(text).collect();
        assert_eq!(stmts[..2], ["let _ = (b ,) ;", "let v = View { a , c } ;"]);
        // The export's own statement follows, and nothing after it (no twin to call).
        assert_eq!(stmts.len(), 3);
        assert!(stmts[2].starts_with("if fast"));
    }

    #[test]
    fn twin_and_view_alone_refuse_each_others_form() {
        let err = expand_view(spec(), export()).unwrap_err().to_string();
        assert_eq!(err, "with_view: takes no twin (see `with_twin`)");
        let spec = quote! { view = struct View as v, unread = (b), };
        let err = expand(spec, export()).unwrap_err().to_string();
        assert_eq!(err, "with_twin: expected `twin = …` after `unread`");
    }

    #[test]
    fn view_alone_names_itself_in_its_refusals() {
        let spec = quote! { view = struct View as v, unread = (z) };
        let err = expand_view(spec, export()).unwrap_err().to_string();
        assert_eq!(
            err,
            "with_view: `z` in `unread` is not a parameter of `ex_`"
        );
    }

    #[test]
    fn twin_is_written_with_the_exports_qualifiers() {
        for twin in [
            quote! { fn t { } },
            quote! { unsafe fn t { } },
            quote! { extern "C" fn t { } },
        ] {
            let spec = quote! { view = struct View as v, unread = (), twin = #twin };
            let err = expand(spec, export()).unwrap_err().to_string();
            assert_eq!(
                err,
                "with_twin: write the twin as `unsafe extern \"C\" fn t`, the export's qualifiers"
            );
        }
        // Without `fn` the twin does not parse: its definition is always `… fn NAME`.
        let spec = quote! { view = struct View as v, unread = (), twin = t { } };
        assert!(expand(spec, export()).is_err());
    }
}
