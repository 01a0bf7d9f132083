:- module(oro_taxonomy,
          [ oro_superclasses/3,         % +Model, +Class, -Supers
            oro_direct_superclasses/3,  % +Model, +Class, -Supers
            oro_subclasses/3,           % +Model, +Class, -Subs
            oro_direct_subclasses/3,    % +Model, +Class, -Subs
            oro_instances/3,            % +Model, +Class, -Instances
            oro_direct_instances/3,     % +Model, +Class, -Instances
            oro_classes_of/3,           % +Model, +Individual, -Classes
            oro_direct_classes_of/3,    % +Model, +Individual, -Classes
            oro_most_specific/3,        % +Model, +Classes, -Specific
            oro_strictly_below/3        % +Model, ?Sub, ?Super
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(error)).
:- use_module(library(oro/oro_store)).
:- use_module(library(oro/reason/oro_reason)).
:- use_module(library(oro/oro_names)).

/** <module> Taxonomy: classes, sub-classes and instances

The eight taxonomy questions of ORO over the inference closure of a
model.  Each answers an ordered set of named IRIs: blank nodes
(anonymous classes) and owl:Nothing are left out, and a class is never
listed among its own super- or sub-classes, nor are the classes
equivalent to it (they are the same class; oro_resource_details/4
lists them as `same_as`).

Errors: asking for the classes of something that is a class, or the
sub-classes or instances of something that is not a class, raises
existence_error(class, X) or existence_error(individual, X).  Classes
and individuals are named as in statements: `'Fork'` (the default
namespace), `oro:'Fork'` or a full IRI.  The model
is a model's name or alias (`default`, the robot id); an unknown one
raises existence_error(agent, Model).
*/

:- rdf_meta
    oro_superclasses(+, r, -),
    oro_direct_superclasses(+, r, -),
    oro_subclasses(+, r, -),
    oro_direct_subclasses(+, r, -),
    oro_instances(+, r, -),
    oro_direct_instances(+, r, -),
    oro_classes_of(+, r, -),
    oro_direct_classes_of(+, r, -).

%!  oro_superclasses(+Model, +Class, -Supers) is det.
%
%   Supers are all the named super-classes of Class, owl:Thing included.
%   @error existence_error(class, Class) if Class is not a class.

oro_superclasses(Model0, Class0, Supers) :-
    oro_resolve_model(Model0, Model),
    must_be_class(Model, Class0, Class),
    findall(S, ( oro_subclass(Model, Class, S),
                 \+ oro_subclass(Model, S, Class)     % not Class, no equivalent
               ), Supers0),
    named_set(Supers0, Supers).

%!  oro_direct_superclasses(+Model, +Class, -Supers) is det.
%
%   Supers are the most specific strict super-classes of Class.

oro_direct_superclasses(Model0, Class, Supers) :-
    oro_resolve_model(Model0, Model),
    oro_superclasses(Model, Class, All),
    most_specific(Model, All, Supers).

%!  oro_subclasses(+Model, +Class, -Subs) is det.
%
%   Subs are all the named sub-classes of Class.

oro_subclasses(Model0, Class0, Subs) :-
    oro_resolve_model(Model0, Model),
    must_be_class(Model, Class0, Class),
    findall(S, ( oro_subclass(Model, S, Class),
                 \+ oro_subclass(Model, Class, S)     % not Class, no equivalent
               ), Subs0),
    named_set(Subs0, Subs).

%!  oro_direct_subclasses(+Model, +Class, -Subs) is det.
%
%   Subs are the most general strict sub-classes of Class.

oro_direct_subclasses(Model0, Class, Subs) :-
    oro_resolve_model(Model0, Model),
    oro_subclasses(Model, Class, All),
    most_general(Model, All, Subs).

%!  oro_instances(+Model, +Class, -Instances) is det.
%
%   Instances are all the named individuals of type Class.

oro_instances(Model0, Class0, Instances) :-
    oro_resolve_model(Model0, Model),
    must_be_class(Model, Class0, Class),
    findall(X, oro_type(Model, X, Class), Xs),
    named_set(Xs, Instances).

%!  oro_direct_instances(+Model, +Class, -Instances) is det.
%
%   Instances are the individuals of which Class is a most specific
%   type.

oro_direct_instances(Model0, Class0, Instances) :-
    oro_resolve_model(Model0, Model),
    oro_resource(Class0, Class),
    oro_instances(Model, Class, All),
    include(direct_instance(Model, Class), All, Instances).

direct_instance(Model, Class, X) :-
    individual_classes(Model, X, Classes),
    most_specific(Model, Classes, Direct),
    memberchk(Class, Direct).

%!  oro_classes_of(+Model, +Individual, -Classes) is det.
%
%   Classes are all the named classes of Individual.
%   @error existence_error(individual, X) if X is a class.
%   @error existence_error(resource, X) if X is unknown.

oro_classes_of(Model0, X0, Classes) :-
    oro_resolve_model(Model0, Model),
    must_be_individual(Model, X0, X),
    individual_classes(Model, X, Classes).

%!  oro_direct_classes_of(+Model, +Individual, -Classes) is det.
%
%   Classes are the most specific named classes of Individual.

oro_direct_classes_of(Model0, X, Classes) :-
    oro_resolve_model(Model0, Model),
    oro_classes_of(Model, X, All),
    most_specific(Model, All, Classes).

individual_classes(Model, X, Classes) :-
    rdf_equal(owl:'NamedIndividual', Named),
    findall(C, ( oro_type(Model, X, C), C \== Named ), Classes0),
    named_set(Classes0, Classes).

		 /*******************************
		 *            HELPERS           *
		 *******************************/

%   must_be_class(+Model, +Name, -Class): Class is the IRI of Name, a
%   class of Model.  must_be_individual(+Model, +Name, -X): X is the IRI
%   of Name, a resource of Model that is not a class.  Names are as
%   oro_resource/2 takes them: `'Fork'`, `oro:'Fork'` or an IRI.

must_be_class(Model, Name, Class) :-
    must_be(nonvar, Name),
    oro_resource(Name, Class),
    (   oro_class(Model, Class)
    ->  true
    ;   existence_error(class, Class)
    ).

must_be_individual(Model, Name, X) :-
    must_be(nonvar, Name),
    oro_resource(Name, X),
    (   oro_class(Model, X)
    ->  existence_error(individual, X)
    ;   known_resource(Model, X)
    ->  true
    ;   existence_error(resource, X)
    ).

known_resource(Model, X) :-
    (   oro_asserted(Model, X, _, _)
    ;   oro_asserted(Model, _, X, _)
    ;   oro_asserted(Model, _, _, X)
    ),
    !.

named_set(List, Set) :-
    rdf_equal(owl:'Nothing', Nothing),
    exclude(unnamed(Nothing), List, Named),
    sort(Named, Set).

unnamed(_, X) :-
    rdf_is_bnode(X),
    !.
unnamed(Nothing, Nothing).

%!  oro_most_specific(+Model, +Classes, -Specific) is det.
%
%   Specific are the classes of Classes with no other class of Classes
%   strictly below them (equivalent classes are at the same level).

oro_most_specific(Model, Classes, Specific) :-
    must_be(list, Classes),
    most_specific(Model, Classes, Specific).

most_specific(Model, Classes, Specific) :-
    exclude(has_strict_sub_in(Model, Classes), Classes, Specific).

has_strict_sub_in(Model, Classes, C) :-
    member(D, Classes),
    D \== C,
    strictly_below(Model, D, C),
    !.

most_general(Model, Classes, General) :-
    exclude(has_strict_super_in(Model, Classes), Classes, General).

has_strict_super_in(Model, Classes, C) :-
    member(D, Classes),
    D \== C,
    strictly_below(Model, C, D),
    !.

%!  oro_strictly_below(+Model, ?Sub, ?Super) is nondet.
%
%   Sub is a sub-class of Super and not equivalent to it.

oro_strictly_below(Model, Sub, Super) :-
    strictly_below(Model, Sub, Super).

strictly_below(Model, Sub, Super) :-
    oro_subclass(Model, Sub, Super),
    \+ oro_subclass(Model, Super, Sub).
