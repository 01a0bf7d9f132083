:- module(oro_reason,
          [ oro_holds/4,                % +Model, ?S, ?P, ?O
            oro_holds_normal/4,         % +Model, ?S, ?P, ?O
            oro_holds_keyed/5,          % +Key, +Model, ?S, ?P, ?O
            oro_holds_bag/6,            % +Model, ?Template, ?S, ?P, ?O, -Bag
            oro_type/3,                 % +Model, ?X, ?Class
            oro_subclass/3,             % +Model, ?Sub, ?Super
            oro_subproperty/3,          % +Model, ?Sub, ?Super
            oro_class/2,                % +Model, ?Class
            oro_property/3,             % +Model, ?Property, ?Kind
            oro_individual/2,           % +Model, ?X
            oro_same_individual/3,      % +Model, +X, -Y
            oro_has_same_individuals/1, % +Model
            oro_functional_property/2,  % +Model, ?Property
            oro_transitive_property/2,  % +Model, ?Property
            oro_property_characteristic/3, % +Model, ?Property, ?Characteristic
            oro_disjoint_classes/3,     % +Model, ?Class1, ?Class2
            oro_disjoint_properties/3,  % +Model, ?Property1, ?Property2
            oro_class_definition/3,     % +Model, ?Class, ?Definition
            oro_property_chain/3,       % +Model, ?Property, ?Links
            oro_property_way/4,         % +Model, +Property, ?Implying, ?Dir
            oro_datatype_member/2,      % +Literal, +Filler
            oro_literal_match/2,        % +Pattern, +Literal
            oro_meta_namespace/1,       % +IRI
            oro_compile_schema/2,       % +Model, -Key
            oro_compiled_schema/2,      % +Model, -Key
            oro_shared_schema/2,        % +Model, -Key
            oro_with_shared_schema/3,   % +Model, -Key, :Goal
            oro_schema_pin/0,
            oro_schema_unpin/0,
            oro_schema_superclass/3,    % +Key, +Class, -Super
            oro_drop_schema/1,          % +Key
            oro_with_schemas/2,         % +ModelKeys, :Goal
            oro_pattern_dependencies/3, % +Model, +Triples, -Predicates
            oro_rdf_list/3              % +Model, +List, -Members
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(error)).
:- use_module(library(oro/oro_store)).
:- use_module(library(oro/oro_names)).
:- use_module(library(oro/reason/oro_reason_tables)).
:- reexport(library(oro/reason/oro_reason_tables),
            [ oro_meta_namespace/1,
              oro_rdf_list/3
            ]).
:- reexport(library(oro/reason/oro_reason_schema),
            [ oro_compile_schema/2,
              oro_compiled_schema/2,
              oro_shared_schema/2,
              oro_with_shared_schema/3,
              oro_schema_pin/0,
              oro_schema_unpin/0,
              oro_schema_superclass/3,
              oro_drop_schema/1,
              oro_with_schemas/2
            ]).
:- use_module(library(oro/reason/oro_reason_schema)).
:- reexport(library(oro/reason/oro_reason_holds),
            [ oro_holds/4,
              oro_holds_normal/4,
              oro_holds_keyed/5,
              oro_holds_bag/6,
              oro_datatype_member/2,
              oro_literal_match/2
            ]).
:- use_module(library(oro/reason/oro_reason_holds)).

/** <module> Reasoning: the inference closure of a model

oro answers every question over the *inference closure* of a model:
what was asserted plus what RDFS, the common OWL property axioms and
the OWL 2 RL class rules entail.  The mechanism is query-time
reasoning over small, precomputed schema closures:

  - The *schema* of a model (class and property hierarchies,
    owl:equivalentClass/Property, owl:inverseOf, symmetric, transitive
    and functional properties, domains, ranges, owl:sameAs, class
    expressions and property chains) is compiled into closure tables,
    once per schema change, and cached under a key.  A schema change
    (in any model or the ontology layer) bumps oro_store's generation
    counter; the next reader recompiles.  The tables replaced are freed
    once no thread reads shared tables (in a pinned region, see
    oro_with_shared_schema/3).
  - Instance triples are never materialised.  oro_holds/4 derives
    them when asked: a triple `S P O` holds if an asserted triple
    `S Q O` (or `O Q S`) implies it through the precomputed *ways* of
    P (sub-properties, equivalent and inverse properties, symmetry),
    or through the transitive closure of a transitive property that
    implies P.  Types come from asserted types, the class hierarchy,
    domains and ranges.  owl:sameAs individuals share everything.

## OWL 2 RL class expressions

Class expressions are read from the schema (restrictions are blank
nodes: their owl:onProperty, owl:hasValue, owl:someValuesFrom,
owl:allValuesFrom, and the RDF lists of owl:intersectionOf,
owl:unionOf, owl:oneOf and owl:propertyChainAxiom) and compiled to
tables (see oro_class_definition/3).  The rules of the OWL 2 RL
profile (W3C OWL 2 Profiles, section 4.3) that apply to them:

  | rule              | meaning                                       | where                  |
  |-------------------|-----------------------------------------------|------------------------|
  | cls-int2, scm-int | an intersection is below each member          | class hierarchy        |
  | cls-uni, scm-uni  | each member is below a union                  | class hierarchy        |
  | cls-int1          | `x` in every member is in the intersection     | derived type           |
  | cls-hv1           | `x : (P value v)` gives `x P v`                | derived triple         |
  | cls-hv2           | `x P v` gives `x : (P value v)`                | derived type           |
  | cls-svf1, cls-svf2| `x P y`, `y : C` gives `x : (P some C)`        | derived type           |
  | cls-avf           | `x : (P only C)`, `x P y` gives `y : C`        | derived type           |
  | cls-oo            | the members of `oneOf` are instances           | derived type           |
  | prp-spo2          | a property chain implies its property          | derived triple         |

A someValuesFrom/allValuesFrom filler may be owl:Thing, a class, or a
datatype (an xsd datatype, rdfs:Literal, or an owl:onDatatype
restriction with min/max inclusive/exclusive facets).  Derived triples
(hasValue and chains) are *virtual edges* of their property: they
imply its super-properties, inverses and transitive closure, and its
domain and range, as asserted edges do.

Derivation is goal-directed.  Class expressions can be cyclic (a
class equivalent to `(p value v)`, whose hasValue edge needs the type
that needs the edge), so every nested derivation of a type, of the
instances of a class or of a chain carries the set of goals in
progress (its *ancestors*): a goal that is a variant of an ancestor
fails, as does any derivation nested more than 64 deep.  For ground
questions ("is x a C?", "does x p y hold?") this loses nothing (a
derivation that needs itself is not one); when instances are
enumerated, an instance found only through a cycle between the
enumerations of two classes may be missed.

The fast paths do not pay for any of this: a schema without class
expressions or chains has no entry or virtual-edge tables, and each
question costs one failing index probe more than before.

Measured by bench/bench_reasoner.pl (SWI-Prolog 9.0.4, AMD EPYC, 50k
asserted triples over the common-sense ontology, IRIs given): a bare
rdf/3 probe 0.5 us, a triple asserted in the model 0.7 us, `x isOn y`
2.6 us, `x isAt y` through isOn 4.5 us, an asserted type 2.6 us, an
inferred type (Cup under Tableware under Artifact) 3.8 us, a false type
4.3 us; recompiling the schema 3.3 ms, done only on the first question
after a schema change.  These are the figures of the reasoner without
the class expressions, to the noise of the machine.  Over the
OpenRobots ontology (oro.owl: 13 hasValue restrictions, intersections,
unions) with 10k bottles: an inferred type 3.1 us, a hasValue edge
(`bottle hasShape cylinderShape`) 4.5 us, all the types of one bottle
0.2 ms, the 10k instances of Artifact 15 ms.

## The parts

This module holds the public predicates that read the inference
closure, and reexports those of its parts, which others should not
load themselves:

  - oro_reason_tables owns the schema closure tables: their
    compilation (hierarchies, ways, domains and ranges, class
    expressions, entries) and the small readers the parts share.
  - oro_reason_schema owns the cache of tables per model and schema
    generation and the pinned readers; the schema-table predicates.
  - oro_reason_holds derives instance triples and types: oro_holds/4
    and its variants, individuals, literal matching.
*/

:- rdf_meta
    oro_type(+, r, r),
    oro_subclass(+, r, r),
    oro_subproperty(+, r, r),
    oro_class(+, r),
    oro_property(+, r, ?),
    oro_individual(+, r),
    oro_property_characteristic(+, r, ?),
    oro_disjoint_classes(+, r, r),
    oro_disjoint_properties(+, r, r),
    oro_class_definition(+, r, ?),
    oro_property_chain(+, r, ?),
    oro_property_way(+, r, r, ?).

		 /*******************************
		 *          PUBLIC API          *
		 *******************************/

%!  oro_type(+Model, ?X, ?Class) is nondet.
%
%   X is an instance of Class in the inference closure of Model.

oro_type(Model, X, Class) :-
    rdf_equal(rdf:type, Type),
    oro_holds(Model, X, Type, Class).

%!  oro_subclass(+Model, ?Sub, ?Super) is nondet.
%
%   Sub is a (reflexive, transitive) sub-class of Super in Model;
%   every class is a sub-class of owl:Thing.  Intersections are below
%   their members and members of unions below the union.

oro_subclass(Model0, Sub0, Super0) :-
    oro_resource(Sub0, Sub),
    oro_resource(Super0, Super),
    pinned(subclass(Model0, Sub, Super)).

%   subclass/3, subproperty/3, class/2, property/3, individual/2,
%   same_individual/3: the bodies of the public predicates, as goals of
%   their own for pinned/1 (a conjunction given to it would be compiled
%   again on every call).

subclass(Model0, Sub, Super) :-
    model_schema(Model0, Model, Key),
    (   nonvar(Sub), nonvar(Super)
    ->  once(sub_class_of(Key, Sub, Super))
    ;   sub_class_of(Key, Model, Sub, Super)
    ).

%!  oro_subproperty(+Model, ?Sub, ?Super) is nondet.
%
%   Sub is a (reflexive, transitive) sub-property of Super in Model.

oro_subproperty(Model0, Sub0, Super0) :-
    oro_resource(Sub0, Sub),
    oro_resource(Super0, Super),
    pinned(subproperty(Model0, Sub, Super)).

subproperty(Model0, Sub, Super) :-
    model_schema(Model0, _, Key),
    (   nonvar(Sub),
        \+ s_prop(Key, Sub, _)
    ->  Super = Sub
    ;   nonvar(Sub), nonvar(Super)
    ->  once(s_subprop(Key, Sub, Super))
    ;   s_subprop(Key, Sub, Super)
    ).

%!  oro_class(+Model, ?Class) is nondet.
%
%   Class is a class of Model: declared, used in the class hierarchy,
%   in a class expression, as a domain or range, or as the type of
%   something.

oro_class(Model0, Class0) :-
    oro_resource(Class0, Class),
    pinned(class(Model0, Class)).

class(Model0, Class) :-
    model_schema(Model0, Model, Key),
    (   nonvar(Class)
    ->  class_key(Key, Model, Class)
    ;   findall(C, ( s_class(Key, C)
                   ; type_only_class(Key, Model, C)
                   ), Classes0),
        sort(Classes0, Classes),
        member(Class, Classes)
    ).

%!  oro_property(+Model, ?Property, ?Kind) is nondet.
%
%   Property is a property of Model, of Kind `object`, `datatype`,
%   `annotation` or `other`.  An undeclared kind is taken from the
%   schema (an inverse is an object property, a sub-property has the
%   kind of its super-property, a datatype range makes a datatype
%   property), else from the values, as OWL reasoners do: `datatype`
%   if the property has a literal value, `object` otherwise.

oro_property(Model, Property0, Kind) :-
    oro_resource(Property0, Property),
    pinned(property(Model, Property, Kind)).

property(Model, Property, Kind) :-
    schema(Model, Key),
    (   nonvar(Property)
    ->  (   s_prop(Key, Property, Kind0)
        ->  true
        ;   once(oro_asserted(Model, _, Property, _))
        ->  Kind0 = other
        ),
        used_kind(Model, Property, Kind0, Kind)
    ;   findall(P-K, s_prop(Key, P, K), Declared),
        findall(P-other, ( rdf_current_predicate(P),
                           \+ s_prop(Key, P, _),
                           \+ oro_meta_namespace(P),
                           once(oro_asserted(Model, _, P, _))
                         ), Used),
        append(Declared, Used, All0),
        sort(All0, All),
        member(Property-Kind0, All),
        used_kind(Model, Property, Kind0, Kind)
    ).

used_kind(Model, Property, other, Kind) :-
    !,
    (   rdf(S, Property, literal(L)),
        oro_asserted(Model, S, Property, literal(L))
    ->  Kind = datatype
    ;   once(oro_asserted(Model, _, Property, _))
    ->  Kind = object
    ;   Kind = other
    ).
used_kind(_, _, Kind, Kind).

%!  oro_individual(+Model, ?X) is nondet.
%
%   X is a named individual of Model (an instance of owl:Thing).

oro_individual(Model0, X0) :-
    oro_resource(X0, X),
    pinned(individual(Model0, X)).

individual(Model0, X) :-
    model_schema(Model0, Model, Key),
    individual_key(Key, Model, X).

%!  oro_same_individual(+Model, +X, -Y) is multi.
%
%   Y is X or an individual owl:sameAs X.

oro_same_individual(Model, X0, Y) :-
    oro_resource(X0, X),
    pinned(same_individual(Model, X, Y)).

same_individual(Model, X, Y) :-
    schema(Model, Key),
    same(Key, X, Y).

%!  oro_has_same_individuals(+Model) is semidet.
%
%   Some individual of Model has other names (owl:sameAs).  If not,
%   oro_same_individual/3 gives every individual itself only.

oro_has_same_individuals(Model) :-
    pinned(has_same_individuals(Model)).

has_same_individuals(Model) :-
    schema(Model, Key),
    once(s_same(Key, _, _)).

%!  oro_functional_property(+Model, ?Property) is nondet.
%
%   Property is declared owl:FunctionalProperty in Model.

oro_functional_property(Model, Property) :-
    pinned(functional_property(Model, Property)).

functional_property(Model, Property) :-
    schema(Model, Key),
    s_functional(Key, Property).

%!  oro_transitive_property(+Model, ?Property) is nondet.
%
%   Property is declared owl:TransitiveProperty in Model.

oro_transitive_property(Model, Property) :-
    pinned(transitive_property(Model, Property)).

transitive_property(Model, Property) :-
    schema(Model, Key),
    s_transitive(Key, Property).

%!  oro_property_characteristic(+Model, ?Property, ?Characteristic) is nondet.
%
%   Property is declared with Characteristic in Model: `functional`,
%   `inverse_functional`, `asymmetric`, `irreflexive` or `reflexive`
%   (transitive and symmetric properties have their own predicates).

oro_property_characteristic(Model, Property, Characteristic) :-
    pinned(property_characteristic(Model, Property, Characteristic)).

property_characteristic(Model, Property, Characteristic) :-
    schema(Model, Key),
    s_char(Key, Property, Characteristic).

%!  oro_disjoint_classes(+Model, ?Class1, ?Class2) is nondet.
%
%   Class1 and Class2 are declared disjoint (owl:disjointWith,
%   owl:complementOf or owl:AllDisjointClasses), either way.

oro_disjoint_classes(Model, Class1, Class2) :-
    pinned(( schema(Model, Key),
             s_disjoint(Key, Class1, Class2)
           )).

%!  oro_disjoint_properties(+Model, ?Property1, ?Property2) is nondet.
%
%   The two properties are declared disjoint (owl:propertyDisjointWith
%   or owl:AllDisjointProperties), either way.

oro_disjoint_properties(Model, Property1, Property2) :-
    pinned(( schema(Model, Key),
             s_prop_disjoint(Key, Property1, Property2)
           )).

%!  oro_class_definition(+Model, ?Class, ?Definition) is nondet.
%
%   Class (usually a blank node) is defined in Model by Definition:
%
%     - has_value(P, V): owl:hasValue restriction;
%     - some_values(P, Filler), all_values(P, Filler):
%       owl:someValuesFrom, owl:allValuesFrom restrictions; Filler is
%       `thing`, class(C) or datatype(Datatype, Facets), Facets a list
%       of min_inclusive-Literal, max_inclusive-Literal,
%       min_exclusive-Literal, max_exclusive-Literal or `unsupported`;
%     - intersection(Classes), union(Classes), one_of(Individuals).

oro_class_definition(Model, Class, Definition) :-
    pinned(( schema(Model, Key),
             s_def(Key, Class, Definition)
           )).

%!  oro_property_chain(+Model, ?Property, ?Links) is nondet.
%
%   The chain Links (a list of properties P or inverse(P)) implies
%   Property (owl:propertyChainAxiom).

oro_property_chain(Model, Property, Links) :-
    pinned(( schema(Model, Key),
             s_chain(Key, Property, Links)
           )).

%!  oro_property_way(+Model, +Property, ?Implying, ?Dir) is nondet.
%
%   An edge `S Implying O` implies `S Property O` (Dir `fwd`) or
%   `O Property S` (Dir `bwd`), through sub-properties, equivalent and
%   inverse properties and symmetry.  Every property implies itself.

oro_property_way(Model, Property, Implying, Dir) :-
    must_be(atom, Property),
    pinned(property_way(Model, Property, Implying, Dir)).

property_way(Model, Property, Implying, Dir) :-
    schema(Model, Key),
    way(Key, Property, Implying, Dir).

%!  oro_pattern_dependencies(+Model, +Triples, -Predicates) is det.
%
%   Predicates is the ordered set of predicates whose asserted triples
%   can change the solutions of the patterns Triples in Model, through
%   sub-properties, inverses, symmetry, transitivity, domains, ranges
%   and owl:sameAs (and rdf:type for an rdfs:subClassOf pattern: a
%   class only used as a type is a sub-class of owl:Thing); it is
%   `[any]` when any triple can (a variable predicate, a variable
%   class, owl:Thing, a class or a property that class expressions or
%   chains derive).  Schema changes are not covered: they can change
%   anything.

oro_pattern_dependencies(Model, Triples, Predicates) :-
    must_be(list, Triples),
    pinned(( schema(Model, Key),
             (   member(rdf(_, P, O), Triples),
                 depends_on_any(Key, P, O)
             ->  Predicates = [any]
             ;   findall(Q, ( member(rdf(_, P, O), Triples),
                              pattern_dependency(Key, P, O, Q)
                            ), Qs),
                 rdf_equal(owl:sameAs, SameAs),
                 sort([SameAs|Qs], Predicates)
             )
           )).

depends_on_any(_, P, _) :-
    var(P),
    !.
depends_on_any(Key, P, O) :-
    rdf_equal(P, rdf:type),
    !,
    (   var(O)
    ->  true
    ;   rdf_equal(O, owl:'Thing')
    ->  true
    ;   s_entry_sub(Key, _, O)
    ->  true
    ).
depends_on_any(Key, P, _) :-
    (   s_virtual_way(Key, P, _, _)
    ->  true
    ;   s_trans_way(Key, P, T, _),
        s_virtual_way(Key, T, _, _)
    ->  true
    ).

pattern_dependency(Key, P, O, Q) :-
    rdf_equal(P, rdf:type),
    !,
    (   Q = P
    ;   s_subj_implies(Key, Q, O)
    ;   s_obj_implies(Key, Q, O)
    ).
pattern_dependency(Key, P, O, Q) :-
    rdf_equal(P, rdfs:subClassOf),
    !,
    (   var(O)                          % a class only used as a type is
    ->  true                            % below itself and owl:Thing
    ;   rdf_equal(O, owl:'Thing')
    ->  true
    ;   \+ s_class(Key, O)
    ),
    rdf_equal(rdf:type, Q).
pattern_dependency(_, P, _, _) :-
    rdf_equal(P, rdfs:subPropertyOf),
    !,
    fail.
pattern_dependency(Key, P, _, Q) :-
    (   way(Key, P, Q, _)
    ;   s_trans_way(Key, P, T, _),
        way(Key, T, Q, _)
    ).
