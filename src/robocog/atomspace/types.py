"""The atom type hierarchy.

Types are plain strings ("ConceptNode", "ListLink") so that atoms stay small and print
as they read. The hierarchy lives in one registry: every type has parents, the root is
"Atom" (with "Node" and "Link" below it), and a link type is either ordered or unordered.
New types are declared with :func:`declare_type`, as OpenCog lets a module add its own.
The short spellings OpenCog's Scheme bindings accept ("Concept", "Evaluation") are
registered as aliases of the full names.
"""

from __future__ import annotations

import sys

#: type -> its direct parents
_PARENTS: dict[str, tuple[str, ...]] = {"Atom": ()}
#: type -> every ancestor, itself included (cached closure)
_ANCESTORS: dict[str, frozenset[str]] = {"Atom": frozenset({"Atom"})}
#: short spelling -> full type name
_ALIASES: dict[str, str] = {}

#: link types whose outgoing set is a set: kept sorted, matched in every order
UNORDERED: set[str] = set()
#: node types (fast membership check)
NODE_TYPES: set[str] = set()
#: link types (fast membership check)
LINK_TYPES: set[str] = set()


class AtomTypeError(ValueError):
    """An unknown or ill-declared atom type."""


def declare_type(name: str, *parents: str) -> str:
    """Declare a new atom type below ``parents`` and return its (interned) name.

    Re-declaring an existing type with the same parents is a no-op, so modules can
    declare what they need without caring about import order.
    """
    if not name or not name.isidentifier():
        raise AtomTypeError(f"bad type name {name!r}")
    if not parents:
        raise AtomTypeError(f"type {name} needs at least one parent")
    for p in parents:
        if p not in _PARENTS:
            raise AtomTypeError(f"unknown parent type {p!r} for {name}")
    name = sys.intern(name)
    if name in _PARENTS:
        if set(_PARENTS[name]) != set(parents):
            raise AtomTypeError(f"type {name} already declared with parents {_PARENTS[name]}")
        return name
    _PARENTS[name] = tuple(parents)
    anc = {name}
    for p in parents:
        anc |= _ANCESTORS[p]
    _ANCESTORS[name] = frozenset(anc)
    if "Node" in anc:
        NODE_TYPES.add(name)
    if "Link" in anc:
        LINK_TYPES.add(name)
        if "UnorderedLink" in anc:
            UNORDERED.add(name)
    for suffix in ("Node", "Link"):
        if name.endswith(suffix) and len(name) > len(suffix):
            short = name[: -len(suffix)]
            if short not in _PARENTS and short not in _ALIASES:
                _ALIASES[short] = name
    return name


def is_type(name: str) -> bool:
    """True if ``name`` is a declared type (full name, not an alias)."""
    return name in _PARENTS


def resolve(name: str) -> str | None:
    """Full type name for a full name or a short alias, or None if unknown."""
    if name in _PARENTS:
        return name
    return _ALIASES.get(name)


def is_a(name: str, ancestor: str) -> bool:
    """True if type ``name`` is ``ancestor`` or inherits from it."""
    anc = _ANCESTORS.get(name)
    return anc is not None and ancestor in anc


def subtypes(ancestor: str) -> frozenset[str]:
    """Every declared type that is ``ancestor`` or inherits from it."""
    return frozenset(t for t, anc in _ANCESTORS.items() if ancestor in anc)


def all_types() -> list[str]:
    """Every declared type, in declaration order."""
    return list(_PARENTS)


_BUILTIN: list[tuple[str, tuple[str, ...]]] = [
    ("Node", ("Atom",)),
    ("Link", ("Atom",)),
    ("OrderedLink", ("Link",)),
    ("UnorderedLink", ("Link",)),
    # nodes
    ("ConceptNode", ("Node",)),
    ("PredicateNode", ("Node",)),
    ("SchemaNode", ("Node",)),
    ("VariableNode", ("Node",)),
    ("GlobNode", ("Node",)),
    ("TypeNode", ("Node",)),
    ("TypeInhNode", ("TypeNode",)),
    ("NumberNode", ("Node",)),
    ("AnchorNode", ("Node",)),
    ("GroundedSchemaNode", ("SchemaNode",)),
    ("GroundedPredicateNode", ("PredicateNode",)),
    ("DefinedSchemaNode", ("SchemaNode",)),
    ("DefinedPredicateNode", ("PredicateNode",)),
    ("InterpretationNode", ("Node",)),
    ("DefinedLinguisticConceptNode", ("ConceptNode",)),
    ("DefinedLinguisticPredicateNode", ("PredicateNode",)),
    # ordered links
    ("ListLink", ("OrderedLink",)),
    ("InheritanceLink", ("OrderedLink",)),
    ("EvaluationLink", ("OrderedLink",)),
    ("ExecutionLink", ("OrderedLink",)),
    ("ImplicationLink", ("OrderedLink",)),
    ("MemberLink", ("OrderedLink",)),
    ("SubsetLink", ("OrderedLink",)),
    ("ContextLink", ("OrderedLink",)),
    ("StateLink", ("OrderedLink",)),
    ("DefineLink", ("OrderedLink",)),
    ("NotLink", ("OrderedLink",)),
    ("AbsentLink", ("OrderedLink",)),
    ("ExecutionOutputLink", ("OrderedLink",)),
    ("TypedVariableLink", ("OrderedLink",)),
    ("VariableList", ("OrderedLink",)),
    ("SignatureLink", ("OrderedLink",)),
    ("TypeChoice", ("OrderedLink",)),
    ("GreaterThanLink", ("OrderedLink",)),
    ("LambdaLink", ("OrderedLink",)),
    ("PutLink", ("OrderedLink",)),
    ("QuoteLink", ("OrderedLink",)),
    ("UnquoteLink", ("OrderedLink",)),
    ("SequentialAndLink", ("OrderedLink",)),
    # a link that may hold free variables; a closed DeleteLink removes what it holds
    ("FreeLink", ("OrderedLink",)),
    ("DeleteLink", ("FreeLink",)),
    # scoping / query links
    ("PatternLink", ("OrderedLink",)),
    ("GetLink", ("PatternLink",)),
    ("SatisfactionLink", ("PatternLink",)),
    ("MeetLink", ("PatternLink",)),
    ("BindLink", ("PatternLink",)),
    ("QueryLink", ("PatternLink",)),
    ("DualLink", ("PatternLink",)),
    # unordered links
    ("SetLink", ("UnorderedLink",)),
    ("AndLink", ("UnorderedLink",)),
    ("OrLink", ("UnorderedLink",)),
    ("ChoiceLink", ("UnorderedLink",)),
    ("PresentLink", ("UnorderedLink",)),
    ("EqualLink", ("UnorderedLink",)),
    ("IdenticalLink", ("UnorderedLink",)),
    ("VariableSet", ("UnorderedLink",)),
    ("SimilarityLink", ("UnorderedLink",)),
    ("EquivalenceLink", ("UnorderedLink",)),
]

#: the rest of OpenCog's core atom types of 2021 (its atom_types.script), with their
#: parents: a program that uses one is read, and the matcher treats it by its kind
#: (an ordered or unordered link, a node) unless it gives the type a meaning of its own
_OPENCOG_2021: list[tuple[str, tuple[str, ...]]] = [
    ("EvaluatableLink", ("Link",)),
    ("CrispOutputLink", ("EvaluatableLink",)),
    ("NumericOutputLink", ("Link",)),
    ("BooleanLink", ("Link",)),
    ("NumericLink", ("Link",)),
    ("TypeInputLink", ("Link",)),
    ("TypeOutputLink", ("Link",)),
    ("AlphaConvertibleLink", ("Link",)),
    ("TrueLink", ("OrderedLink", "CrispOutputLink")),
    ("FalseLink", ("OrderedLink", "CrispOutputLink")),
    ("SequentialOrLink", ("OrderedLink", "CrispOutputLink", "BooleanLink")),
    ("AlwaysLink", ("PresentLink",)),
    ("ParallelLink", ("UnorderedLink", "EvaluatableLink")),
    ("ThreadJoinLink", ("ParallelLink",)),
    ("ExecuteThreadedLink", ("OrderedLink",)),
    ("LexicalNode", ("PredicateNode",)),
    ("AnyNode", ("Node",)),
    ("Connector", ("OrderedLink",)),
    ("ConnectorDir", ("LexicalNode",)),
    ("Bond", ("LexicalNode",)),
    ("ConnectorSeq", ("OrderedLink",)),
    ("ConnectorSet", ("UnorderedLink",)),
    ("ConnectorChoice", ("ChoiceLink",)),
    ("Section", ("OrderedLink",)),
    ("ShapeLink", ("ConnectorSeq",)),
    ("CrossSection", ("Section",)),
    ("LocalQuoteLink", ("OrderedLink",)),
    ("DontExecLink", ("OrderedLink",)),
    ("ReplacementLink", ("OrderedLink",)),
    ("UniqueLink", ("FreeLink",)),
    ("ScopeLink", ("Section", "AlphaConvertibleLink")),
    ("RewriteLink", ("ScopeLink",)),
    ("PrenexLink", ("RewriteLink",)),
    ("JoinLink", ("PrenexLink",)),
    ("MinimalJoinLink", ("JoinLink",)),
    ("UpperSetLink", ("JoinLink",)),
    ("MaximalJoinLink", ("JoinLink",)),
    ("SatisfyingLink", ("PatternLink",)),
    ("TypeCoInhNode", ("TypeNode",)),
    ("DefinedTypeNode", ("TypeNode",)),
    ("TypeIntersectionLink", ("TypeChoice",)),
    ("ArrowLink", ("ConnectorSeq", "TypeOutputLink")),
    ("TypedAtomLink", ("UniqueLink",)),
    ("IntervalLink", ("OrderedLink",)),
    ("VirtualLink", ("CrispOutputLink",)),
    ("IsClosedLink", ("UnorderedLink", "VirtualLink")),
    ("IsTrueLink", ("UnorderedLink", "VirtualLink")),
    ("IsFalseLink", ("UnorderedLink", "VirtualLink")),
    ("AlphaEqualLink", ("UnorderedLink", "VirtualLink")),
    ("ExclusiveLink", ("UnorderedLink", "VirtualLink")),
    ("FunctionLink", ("FreeLink",)),
    ("FoldLink", ("FunctionLink",)),
    ("ArithmeticLink", ("FoldLink", "NumericLink", "NumericOutputLink")),
    ("PlusLink", ("ArithmeticLink",)),
    ("MinusLink", ("PlusLink",)),
    ("TimesLink", ("ArithmeticLink",)),
    ("DivideLink", ("TimesLink",)),
    ("MinLink", ("FunctionLink", "NumericOutputLink")),
    ("MaxLink", ("FunctionLink", "NumericOutputLink")),
    ("HeavisideLink", ("FunctionLink", "NumericOutputLink")),
    ("RandomNumberLink", ("FunctionLink", "NumericOutputLink")),
    ("AccumulateLink", ("FunctionLink", "NumericOutputLink")),
    ("ArityLink", ("FunctionLink", "NumericOutputLink")),
    ("TimeLink", ("FunctionLink", "NumericOutputLink")),
    ("ValueOfLink", ("FunctionLink", "NumericOutputLink")),
    ("StreamValueOfLink", ("ValueOfLink",)),
    ("TruthValueOfLink", ("ValueOfLink",)),
    ("StrengthOfLink", ("ValueOfLink",)),
    ("ConfidenceOfLink", ("ValueOfLink",)),
    ("CountOfLink", ("ValueOfLink",)),
    ("SetValueLink", ("FunctionLink",)),
    ("SetTVLink", ("SetValueLink", "EvaluatableLink")),
    ("PredicateFormulaLink", ("ScopeLink", "EvaluatableLink")),
    ("DynamicFormulaLink", ("ScopeLink", "EvaluatableLink")),
    ("RandomChoiceLink", ("FunctionLink",)),
    ("CondLink", ("FunctionLink",)),
    ("SleepLink", ("FunctionLink", "NumericOutputLink")),
    ("MapLink", ("FunctionLink",)),
    ("ProcedureNode", ("Node",)),
    ("GroundedProcedureNode", ("ProcedureNode",)),
    ("QuantityLink", ("OrderedLink",)),
    ("IntensionalInheritanceLink", ("InheritanceLink",)),
    ("ExtensionalSimilarityLink", ("SimilarityLink",)),
    ("IntensionalSimilarityLink", ("SimilarityLink",)),
    ("ExistsLink", ("ScopeLink", "CrispOutputLink")),
    ("ForAllLink", ("ScopeLink",)),
    ("SatisfyingSetScopeLink", ("ScopeLink",)),
    ("SatisfyingSetLink", ("Link",)),
    ("IntensionalImplicationLink", ("ImplicationLink",)),
    ("ExtensionalImplicationLink", ("ImplicationLink",)),
    ("IntensionalEquivalenceLink", ("EquivalenceLink",)),
    ("ExtensionalEquivalenceLink", ("EquivalenceLink",)),
    ("ImplicationScopeLink", ("ScopeLink",)),
    ("IntensionalImplicationScopeLink", ("ImplicationScopeLink",)),
    ("ExtensionalImplicationScopeLink", ("ImplicationScopeLink",)),
    ("EquivalenceScopeLink", ("ScopeLink",)),
    ("IntensionalEquivalenceScopeLink", ("EquivalenceScopeLink",)),
    ("ExtensionalEquivalenceScopeLink", ("EquivalenceScopeLink",)),
    ("AssociativeLink", ("OrderedLink",)),
    ("AttractionLink", ("OrderedLink",)),
]

for _name, _parents in _BUILTIN + _OPENCOG_2021:
    declare_type(_name, *_parents)

#: link types whose outgoing set declares variables
VARIABLE_DECLS = frozenset({"VariableList", "VariableSet", "TypedVariableLink"})
#: link types that run the pattern matcher when executed
QUERY_TYPES = frozenset({"GetLink", "BindLink", "QueryLink", "MeetLink", "SatisfactionLink"})
