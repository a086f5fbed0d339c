"""Type each inlined overload once per signature.

The kernels pick a kind's code at compile time through overloads with ``inline="always"``
(rtfgu.kernels.dispatch ``_overloaded``): the body for a kind the scene has, another for a
kind it lacks. numba (0.68.1, the version read) types such an overload's body again at every call of its
template (``_OverloadFunctionTemplate.generic``, numba/core/typing/templates.py): once per
call site and once more at every round of type propagation that revisits the call, with
the same argument types each time. In a render kernel the light loop was typed 7 times and
each shape kind's shadow test 25 times, for the same signature: most of a kernel's compile.

What stays is one typing per signature, plus one per call site when the typed inliner
puts the body in (``InlineWorker.update_type_and_call_maps`` types each copy under its new
variable names). ``cache_inline_typing()`` keeps the first typing of each (template, typing context,
argument types, keywords, target flags) and answers later calls with it. That is what the
template would compute again: the body's IR, its type map and call types are kept in
``template._inline_overloads[args]`` by the first call (as numba itself keeps them), and the
inliner copies that IR at each call site before changing it (``InlineWorker.inline_ir``),
so one typing serves every site. Only the ``inline="always"`` case is cached; numba's own
path is used for every other overload, and wherever its internals are not the ones this
was written against (the patch then does nothing).

Besides typing it, numba compiles such a body to machine code on its own when the
template first meets a signature (``_OverloadFunctionTemplate._build_impl``: "Make sure
that the implementation can be fully compiled", and ``generic``'s ``get_call_template``),
although the template then marks it "always inlined" and no call ever reaches that code:
every body typed, lowered, optimised by LLVM and made machine code for nothing, and
each body inlined inside it compiled so again. ``compile_inline_bodies_once()`` hands such
a template a dispatcher that does not compile; the body is still typed (``generic``'s
``type_inference_stage``), where a typing error is reported as before, and inlined. A
render kernel's compile is then the kernel's alone.
"""
from __future__ import annotations

_CACHE_ATTRIBUTE = "_rtfgu_inline_signatures"


def cache_inline_typing() -> bool:
    """Install the cache on numba's overload template; True when installed (or already
    installed), False where numba's template does not have the expected shape."""
    try:
        from numba.core import targetconfig
        from numba.core.typing.templates import _OverloadFunctionTemplate
    except ImportError:
        return False
    generic = _OverloadFunctionTemplate.generic
    if getattr(generic, "_rtfgu_cached", False):
        return True
    if not hasattr(_OverloadFunctionTemplate, "_get_impl"):
        return False

    def cached_generic(self, args, kws):
        inline = getattr(self, "_inline", None)
        if inline is None or not inline.is_always_inline:
            return generic(self, args, kws)
        cache = self.__class__.__dict__.get(_CACHE_ATTRIBUTE)
        if cache is None:
            cache = {}
            setattr(self.__class__, _CACHE_ATTRIBUTE, cache)
        try:
            key = (self.context, tuple(args), tuple(sorted(kws.items())),
                   targetconfig.ConfigStack.top_or_none())
            hash(key)
        except TypeError:   # an unhashable argument type: type it as numba would
            return generic(self, args, kws)
        if key in cache:
            sig = cache[key]
            # The kept typing must still be there for the inliner (typed_passes.InlineOverloads).
            if sig is None or sig.args in self._inline_overloads:
                return sig
        sig = generic(self, args, kws)
        cache[key] = sig
        return sig

    cached_generic._rtfgu_cached = True
    cached_generic.numba_generic = generic   # numba's own, for the tests to compare with
    cached_generic.__doc__ = generic.__doc__
    _OverloadFunctionTemplate.generic = cached_generic
    return True


def compile_inline_bodies_once() -> bool:
    """Give each ``inline="always"`` overload template a jit decorator whose dispatchers do
    not compile (``_can_compile``, as ``Dispatcher.disable_compile`` sets it); True when
    installed (or already installed), False where numba's template does not have the
    expected shape."""
    try:
        from numba.core.typing.templates import _OverloadFunctionTemplate
    except ImportError:
        return False
    get_jit_decorator = getattr(_OverloadFunctionTemplate, "_get_jit_decorator", None)
    if get_jit_decorator is None:
        return False
    if getattr(get_jit_decorator, "_rtfgu_no_compile", False):
        return True

    def inline_jit_decorator(self):
        jitter = get_jit_decorator(self)
        inline = getattr(self, "_inline", None)
        if inline is None or not inline.is_always_inline:
            return jitter

        def typed_only(**options):
            decorate = jitter(**options)

            def wrap(pyfunc):
                dispatcher = decorate(pyfunc)
                # What Dispatcher.disable_compile sets; it asserts a compiled signature, and
                # this dispatcher has none and needs none.
                dispatcher._can_compile = False
                return dispatcher
            return wrap
        return typed_only

    inline_jit_decorator._rtfgu_no_compile = True
    inline_jit_decorator.numba_get_jit_decorator = get_jit_decorator
    _OverloadFunctionTemplate._get_jit_decorator = inline_jit_decorator
    return True
